//===- wash/openmp/for_each.hpp - the OpenMP particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/exact_sum.hpp>
#include <wash/detail/profile.hpp>

#include <omp.h>

#include <algorithm>
#include <exception>
#include <limits>
#include <vector>

namespace wash::openmp {

/// The summary weighs the steps' CPU time against this many threads.
inline const bool loopThreadsSet = (detail::loopThreads = omp_get_max_threads(), true);

/// Particles per dynamic chunk: 256, or a 64th of a thread's share when that
/// is more. A thread's chunk reads its neighbours from the rows of cells
/// around it; with small chunks the threads take turns along the same rows and
/// each pulls all of them into its own cache. At a million particles in 2D
/// those rows outgrow the cache, and 8192-particle chunks made the 2-thread
/// seed 4-6 % faster (docs/performance.md) while 64 chunks a thread still even
/// out the work.
inline std::size_t chunkFor(std::size_t n) {
  return std::max<std::size_t>(256, n / (64 * std::size_t(omp_get_max_threads())));
}

/// The exception a particle loop's body threw at the smallest position, kept
/// to be rethrown after the parallel region: one escaping the region would
/// end the program with std::terminate (SIGABRT) instead of the message and
/// exit status a serial run gives. The smallest position is the one a serial
/// loop stops at, so the message is the same at every thread count.
class FirstError {
public:
  void capture(std::size_t position) {
#pragma omp critical(wash_first_error)
    if (position < position_) {
      position_ = position;
      error_ = std::current_exception();
    }
  }
  void rethrow() const {
    if (error_)
      std::rethrow_exception(error_);
  }

private:
  std::size_t position_ = std::numeric_limits<std::size_t>::max();
  std::exception_ptr error_;
};

/// The particle loop of the OpenMP backend (backend.hpp makes it a backend type).
struct Loop {
  static constexpr const char *name = "openmp";

  /// Calls body(i) for every position in `rows` (the real particles), on all
  /// threads; body returns whether what it wrote is finite, and the loop whether
  /// every call did. Each call writes only particle i (the translator checked),
  /// so no atomics are needed, and the result does not depend on the thread
  /// count. Dynamic chunks even out uneven neighbour counts; particles are
  /// cell-sorted, so a chunk is a compact region. An exception from the body
  /// is rethrown once the loop is over (FirstError).
  template <typename Body>
  static bool forEachParticleChecked(const std::vector<backend::Index> &rows, Body body) {
    const std::size_t n = rows.size();
    bool all = true;
    FirstError error;
#pragma omp parallel for schedule(dynamic, chunkFor(n)) reduction(&& : all)
    for (std::size_t k = 0; k < n; ++k) {
      try {
        const bool finite = body(rows[k]);
        all = all && finite;
      } catch (...) {
        error.capture(k);
      }
    }
    error.rethrow();
    return all;
  }

  /// The same loop for a body with nothing to report.
  template <typename Body>
  static void forEachParticle(const std::vector<backend::Index> &rows, Body body) {
    forEachParticleChecked(rows, backend::reportingNothing(body));
  }

  /// The exact sum of values[row] over `rows`: one sum per thread, merged.
  /// Merging is exact, so the thread count and the split do not matter.
  static detail::ExactSum sum(const std::vector<double> &values,
                              const std::vector<backend::Index> &rows) {
    const std::size_t n = rows.size();
    detail::ExactSum total;
#pragma omp parallel if (n >= 16384)
    {
      const std::size_t threads = std::size_t(omp_get_num_threads());
      const std::size_t t = std::size_t(omp_get_thread_num());
      const std::size_t begin = n * t / threads, end = n * (t + 1) / threads;
      detail::ExactSum mine;
      mine.addEach(end - begin, [&](std::size_t k) { return values[rows[begin + k]]; });
#pragma omp critical(wash_exact_sum)
      total.merge(mine);
    }
    return total;
  }
};

} // namespace wash::openmp
