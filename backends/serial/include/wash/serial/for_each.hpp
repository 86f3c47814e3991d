//===- wash/serial/for_each.hpp - the serial particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/backend/reduce.hpp>

#include <vector>

namespace wash::serial {

/// The particle loop of the serial backend (backend.hpp makes it a backend type).
struct Loop {
  static constexpr const char *name = "serial";

  /// Calls body(i) for every position in `rows` (the real particles), in order;
  /// body returns whether what it wrote is finite, and the loop whether every
  /// call did.
  template <typename Body>
  static bool forEachParticleChecked(const std::vector<backend::Index> &rows, Body body) {
    bool all = true;
    for (backend::Index i : rows)
      all &= body(i);
    return all;
  }

  /// The same loop for a body with nothing to report.
  template <typename Body>
  static void forEachParticle(const std::vector<backend::Index> &rows, Body body) {
    forEachParticleChecked(rows, backend::reportingNothing(body));
  }

  /// The exact sum of values[row] over `rows`.
  static detail::ExactSum sum(const std::vector<double> &values,
                              const std::vector<backend::Index> &rows) {
    return backend::sumRows(values, rows);
  }
};

} // namespace wash::serial
