//===- wash/sph/diagnostics.hpp - per-particle sums to monitor --*- C++ -*-===//
//
// Helpers a Sum reduction kernel returns, to watch conservation.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/wash.hpp>

namespace wash::sph {

/// m v^2 / 2.
inline double kinetic_energy(const wash::Particle &p) {
  wash::ParticleVec v = p.get_vel();
  return p.get_mass() * 0.5 * v.dot(v);
}

} // namespace wash::sph
