//===- wash/mpi/for_each.hpp - the particle loop of an MPI rank ---*- C++ -*-===//
#pragma once

#include <wash/openmp/for_each.hpp>

namespace wash::mpi {

/// Calls body(i) for every owned particle position, on all OpenMP threads of
/// this rank (hybrid MPI + OpenMP): the OpenMP backend's loop.
using wash::openmp::forEachParticle;

} // namespace wash::mpi
