//===- HaloExchange.h - what MPI must send before a force kernel -*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Kernel::HaloFields and HaloSends of one kernel.
struct KernelHalo {
  FieldSet Fields, Sends;
};

/// For each force kernel, the fields that must be current on halo particles
/// (copies of another rank's particles) before it runs: pos, to find them as
/// neighbours, and every field the kernel reads through neighbours
/// (KernelHalo::Fields), and what is actually exchanged before the kernel
/// (KernelHalo::Sends). The first kernel of a neighbour search rebuilds the
/// halo and sends all its fields; a later kernel of the same search sends
/// only the fields it needs that some kernel wrote since they were last sent.
/// One per kernel, in order (empty but for force kernels). Reads the kernels'
/// Kind, NeighbourReads and OwnWrites (summariseAccesses) and SearchGroup,
/// an index into Searches (planNeighbourSearch).
std::vector<KernelHalo> planHalos(const std::vector<Kernel> &Kernels,
                                  const std::vector<SearchGroup> &Searches);

} // namespace wash::tr
