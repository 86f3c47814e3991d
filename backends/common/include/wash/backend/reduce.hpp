//===- wash/backend/reduce.hpp - reduction kernels, shared memory --*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/exact_sum.hpp>
#include <wash/detail/reduction.hpp>

#include <vector>

namespace wash::backend {

/// The exact sum of values[p] over the positions p in `rows`, on one thread.
inline detail::ExactSum sumRows(const std::vector<double> &values, const std::vector<Index> &rows) {
  detail::ExactSum sum;
  sum.addEach(rows.size(), [&](std::size_t k) { return values[rows[k]]; });
  return sum;
}

/// The Min or Max of values[p] over the real particles p in `rows`, combined
/// in ascending id order (ids of real particles are 0..rows.size()-1).
inline double reduceById(const Column<std::uint64_t> &ids, const std::vector<double> &values,
                         const std::vector<Index> &rows, detail::ReduceOp op) {
  std::vector<double> byId(rows.size());
  for (Index p : rows)
    byId[ids[p]] = values[p];
  return detail::reduceInIdOrder(byId, op);
}

} // namespace wash::backend
