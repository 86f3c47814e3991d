//===- wash/detail/reduction.hpp - the reduction every runtime does -*- C++ -*-===//
#pragma once

#include <wash/detail/exact_sum.hpp>

#include <limits>
#include <vector>

namespace wash::detail {

enum class ReduceOp { Sum, Min, Max };

/// The reduction of values given in ascending id order (docs/semantics.md): a
/// Sum is exact, rounded once (ExactSum), so the order does not matter to it.
inline double reduceInIdOrder(const std::vector<double> &byId, ReduceOp op) {
  if (op == ReduceOp::Sum) {
    ExactSum sum;
    for (double v : byId)
      sum.add(v);
    return sum.round<double>();
  }
  double r = op == ReduceOp::Min ? std::numeric_limits<double>::infinity()
                                 : -std::numeric_limits<double>::infinity();
  for (double v : byId)
    r = op == ReduceOp::Min ? (v < r ? v : r) : (v > r ? v : r);
  return r;
}

} // namespace wash::detail
