//===- wash/serial/for_each.hpp - the serial particle loop --------*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>

#include <vector>

namespace wash::serial {

/// Calls body(i) for every position in `rows` (the real particles), in order.
template <typename Body>
inline void forEachParticle(const std::vector<backend::Index> &rows, Body body) {
  for (backend::Index i : rows)
    body(i);
}

/// The same loop for a body that returns whether what it wrote is finite:
/// returns whether every call did.
template <typename Body>
inline bool forEachParticleChecked(const std::vector<backend::Index> &rows, Body body) {
  bool all = true;
  for (backend::Index i : rows)
    all &= body(i);
  return all;
}

} // namespace wash::serial
