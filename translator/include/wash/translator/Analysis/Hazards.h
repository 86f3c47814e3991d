//===- Hazards.h - fields that need a snapshot ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// A force kernel that writes a field on its own particle and reads the same
/// field on neighbours would see a mix of old and new values once particles
/// run in parallel: such fields (and only those) need a snapshot copy taken
/// before the kernel. Returns Kernel::Hazards of each kernel, in order (empty
/// but for force kernels), from their Kind, OwnWrites and NeighbourReads
/// (summariseAccesses).
std::vector<FieldSet> findHazards(const std::vector<Kernel> &Kernels);

} // namespace wash::tr
