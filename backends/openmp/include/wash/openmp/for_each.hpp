//===- wash/openmp/for_each.hpp - the OpenMP particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>

#include <vector>

namespace wash::openmp {

/// Calls body(i) for every position in `rows` (the real particles), on all
/// threads; body returns whether what it wrote is finite, and the loop whether
/// every call did. Each call writes only particle i (the translator checked),
/// so no atomics are needed, and the result does not depend on the thread
/// count. Dynamic chunks even out uneven neighbour counts; particles are
/// cell-sorted, so a chunk is a compact region.
template <typename Body>
inline bool forEachParticleChecked(const std::vector<backend::Index> &rows, Body body) {
  const std::size_t n = rows.size();
  bool all = true;
#pragma omp parallel for schedule(dynamic, 256) reduction(&& : all)
  for (std::size_t k = 0; k < n; ++k) {
    const bool finite = body(rows[k]);
    all = all && finite;
  }
  return all;
}

/// The same loop for a body with nothing to report.
template <typename Body>
inline void forEachParticle(const std::vector<backend::Index> &rows, Body body) {
  forEachParticleChecked(rows, backend::reportingNothing(body));
}

} // namespace wash::openmp
