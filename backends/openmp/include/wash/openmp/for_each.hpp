//===- wash/openmp/for_each.hpp - the OpenMP particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>

namespace wash::openmp {

/// Calls body(i) for every particle index, on all threads. Each call writes
/// only particle i (the translator checked), so no atomics are needed, and the
/// result does not depend on the thread count. Dynamic chunks even out uneven
/// neighbour counts; particles are cell-sorted, so a chunk is a compact region.
template <typename Body> inline void forEachParticle(backend::Index n, Body body) {
#pragma omp parallel for schedule(dynamic, 256)
  for (backend::Index i = 0; i < n; ++i)
    body(i);
}

} // namespace wash::openmp
