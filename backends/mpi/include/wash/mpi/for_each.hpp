//===- wash/mpi/for_each.hpp - the particle loop of an MPI rank ---*- C++ -*-===//
#pragma once

#include <wash/openmp/for_each.hpp>

#include <chrono>

namespace wash::mpi {

/// Seconds this rank has spent in particle loops since the domain was last
/// balanced: its work as measured, which is what the balance evens out (a
/// rank on a slower or busier core gets fewer particles).
inline double &busySeconds() {
  static double seconds = 0.0;
  return seconds;
}

/// Adds the time of the enclosing scope to busySeconds().
class BusyClock {
public:
  ~BusyClock() {
    busySeconds() +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// The particle loop of an MPI rank: the OpenMP backend's loop, on all
/// threads of this rank (hybrid MPI + OpenMP), timed.
struct Loop {
  template <typename Body>
  static void forEachParticle(const std::vector<backend::Index> &rows, Body body) {
    BusyClock clock;
    wash::openmp::Loop::forEachParticle(rows, body);
  }
  /// For a body that returns whether what it wrote is finite: returns
  /// whether every call did (on this rank).
  template <typename Body>
  static bool forEachParticleChecked(const std::vector<backend::Index> &rows, Body body) {
    BusyClock clock;
    return wash::openmp::Loop::forEachParticleChecked(rows, body);
  }
  /// This rank's exact sum of values[row] over `rows`, on all its threads.
  static detail::ExactSum sum(const std::vector<double> &values,
                              const std::vector<backend::Index> &rows) {
    return wash::openmp::Loop::sum(values, rows);
  }
};

} // namespace wash::mpi
