//===- wash/detail/cell.hpp - the canonical cell of a coordinate -*- C++ -*-===//
//
// Part of the neighbour-ordering contract (docs/semantics.md): the cell of a
// coordinate in a grid anchored at the origin is floor(x / cellSize), the
// division rounded as written, then floored. Every runtime's cells come from
// here, so that they cannot drift apart.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cmath>
#include <cstdint>

namespace wash::detail {

/// Grid coordinate of x in a grid of cell size `cellSize` anchored at 0.
inline std::int64_t cellCoordinate(double x, double cellSize) {
  return static_cast<std::int64_t>(std::floor(x / cellSize));
}

} // namespace wash::detail
