//===- wash/serial/for_each.hpp - the serial particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>

namespace wash::serial {

/// Calls body(i) for every particle index, in order.
template <typename Body> inline void forEachParticle(backend::Index n, Body body) {
  for (backend::Index i = 0; i < n; ++i)
    body(i);
}

} // namespace wash::serial
