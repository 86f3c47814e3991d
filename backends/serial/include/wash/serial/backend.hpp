//===- wash/serial/backend.hpp - the serial backend type -----------*- C++ -*-===//
#pragma once

#include <wash/backend/shared_memory.hpp>
#include <wash/serial/for_each.hpp>

namespace wash::serial {

template <int D> using Backend = backend::SharedMemoryBackend<D, Loop>;

} // namespace wash::serial
