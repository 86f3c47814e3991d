//===- SummariseAccesses.h - raw accesses to per-kernel sets ----*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Kernel::OwnReads, OwnWrites and NeighbourReads of one kernel.
struct AccessSets {
  FieldSet OwnReads, OwnWrites, NeighbourReads;
};

/// The access sets of each kernel, in order, from its Kind and raw Accesses.
/// SearchesBySmoothingLength (Model::searchesBySmoothingLength): every force
/// kernel's search reads its particle's smoothing length; with
/// SymmetricSupport (Settings::SymmetricSupport) its neighbours' too.
std::vector<AccessSets> summariseAccesses(const std::vector<Kernel> &Kernels,
                                          bool SearchesBySmoothingLength,
                                          bool SymmetricSupport = false);

} // namespace wash::tr
