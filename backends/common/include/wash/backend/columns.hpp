//===- wash/backend/columns.hpp - structure-of-arrays storage -----*- C++ -*-===//
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wash::backend {

/// Particle index in the current storage order (which changes when particles
/// are reordered by cell; the id does not).
using Index = std::uint32_t;

/// One property of every particle. Plain std::vector: contiguous, and
/// operator[] compiles to a direct array access.
template <typename T> using Column = std::vector<T>;

/// Reorders `column` so that new[k] = old[order[k]]; `order` may also select a
/// subset (the column then shrinks to order.size()). The spare storage is one
/// buffer per element type, shared by all columns of that type and kept between
/// calls: reordering costs one extra column per type, not a copy of everything.
template <typename T> void permute(Column<T> &column, const std::vector<Index> &order) {
  static Column<T> scratch;
  scratch.resize(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    scratch[k] = column[order[k]];
  column.swap(scratch);
}

} // namespace wash::backend
