//===- wash/mpi/for_each.hpp - the particle loop of an MPI rank ---*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>

#include <vector>

namespace wash::mpi {

/// Calls body(i) for every owned particle position, on all OpenMP threads of
/// this rank (hybrid MPI + OpenMP); each call writes only particle i.
template <typename Body>
inline void forEachOwned(const std::vector<backend::Index> &owned, Body body) {
  const std::size_t n = owned.size();
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t k = 0; k < n; ++k)
    body(owned[k]);
}

} // namespace wash::mpi
