//===- SummariseAccesses.h - raw accesses to per-kernel sets ----*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// Fills OwnReads, OwnWrites and NeighbourReads of every kernel from its raw
/// accesses.
void summariseAccesses(Model &M);

} // namespace wash::tr
