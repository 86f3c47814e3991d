//===- wash/openmp/backend.hpp - the OpenMP backend type -----------*- C++ -*-===//
#pragma once

#include <wash/backend/shared_memory.hpp>
#include <wash/openmp/for_each.hpp>

namespace wash::openmp {

template <int D> using Backend = backend::SharedMemoryBackend<D, Loop>;

} // namespace wash::openmp
