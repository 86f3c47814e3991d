//===- wash/backend/reduce.hpp - reduction kernels, shared memory --*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/exact_sum.hpp>
#include <wash/detail/reduction.hpp>

#include <algorithm>
#include <utility>
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

/// The Min or Max of values[p] over some real particles' rows, combined in
/// ascending id order.
inline double reduceRowsById(const Column<std::uint64_t> &ids, const std::vector<double> &values,
                             const std::vector<Index> &rows, detail::ReduceOp op) {
  std::vector<std::pair<std::uint64_t, double>> byId(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k)
    byId[k] = {ids[rows[k]], values[rows[k]]};
  std::sort(byId.begin(), byId.end(),
            [](const auto &a, const auto &b) { return a.first < b.first; });
  std::vector<double> inOrder(byId.size());
  for (std::size_t k = 0; k < byId.size(); ++k)
    inOrder[k] = byId[k].second;
  return detail::reduceInIdOrder(inOrder, op);
}

} // namespace wash::backend
