//===- Hoisting.h - which per-neighbour expressions get a column -*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// The expressions findHoistable found (Found) whose value, computed for
/// every row right before each force kernel that reaches it, is the one the
/// loop would compute: every field it reads is one the kernel reads through
/// neighbours (so the search or refresh before the kernel brought it up to
/// date on every row, copies included) and none is one a kernel writes on
/// its particle while reading it through neighbours (a hazard, read from a
/// snapshot). Reads the kernels' Kind, NeighbourReads (summariseAccesses)
/// and Hazards and DisjointTypeWrites (findHazards).
std::vector<HoistedExpr> planHoists(const std::vector<HoistedExpr> &Found,
                                    const std::vector<Kernel> &Kernels);

} // namespace wash::tr
