//===- Hazards.h - fields that need a snapshot ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Kernel::Hazards and Kernel::DisjointTypeWrites of one kernel.
struct KernelHazards {
  FieldSet Snapshot;      ///< Written on the own particle, read through neighbours.
  FieldSet DisjointTypes; ///< The same, but never on a particle of both kinds.
};

/// A force kernel that writes a field on its own particle and reads the same
/// field on neighbours would see a mix of old and new values once particles
/// run in parallel: such fields (and only those) need a snapshot copy taken
/// before the kernel. Not when the kernel runs for one particle type and
/// filters its neighbours to another: no particle it writes is then a
/// neighbour it reads, since a particle's type stays what it was when the
/// kernel started (force kernels cannot set it, docs/semantics.md). Returns
/// the hazards of each kernel, in order (empty but for force kernels), from
/// their Kind, ParticleType, NeighbourType, OwnWrites and NeighbourReads
/// (summariseAccesses).
std::vector<KernelHazards> findHazards(const std::vector<Kernel> &Kernels);

/// Whether the particles K runs for and the neighbours it reads have no type
/// in common (both named, and different).
bool writesAndReadsDisjointTypes(const Kernel &K);

} // namespace wash::tr
