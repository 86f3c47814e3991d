//===- wash/detail/reduction.hpp - the reduction every runtime does -*- C++ -*-===//
#pragma once

#include <limits>
#include <vector>

namespace wash::detail {

enum class ReduceOp { Sum, Min, Max };

/// The reduction of values given in ascending id order (docs/semantics.md).
inline double reduceInIdOrder(const std::vector<double> &byId, ReduceOp op) {
  double r = op == ReduceOp::Sum   ? 0.0
             : op == ReduceOp::Min ? std::numeric_limits<double>::infinity()
                                   : -std::numeric_limits<double>::infinity();
  for (double v : byId)
    r = op == ReduceOp::Sum ? r + v : op == ReduceOp::Min ? (v < r ? v : r) : (v > r ? v : r);
  return r;
}

} // namespace wash::detail
