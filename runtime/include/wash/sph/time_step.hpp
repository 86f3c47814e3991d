//===- wash/sph/time_step.hpp - time-step criteria --------------*- C++ -*-===//
//
// A particle's largest stable time step by each criterion; a reduction kernel
// returns the smallest (wash::Reduction::Min into "time_step"). Formulas and
// references: docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cmath>
#include <limits>

namespace wash::sph {

/// Courant: C h / v_sig (v_sig: the signal velocity, or c + |v|).
inline double courant_time_step(double courant, double h, double signalVelocity) {
  return courant * h / signalVelocity;
}
/// Force (Monaghan 1992): C_f sqrt(h / |a|); +inf without acceleration.
inline double force_time_step(double factor, double h, double acceleration) {
  return acceleration > 0.0 ? factor * std::sqrt(h / acceleration)
                            : std::numeric_limits<double>::infinity();
}
/// Viscous diffusion (Morris et al. 1997): C_v h^2 / nu, nu the kinematic
/// viscosity (C_v = 0.125); +inf for nu = 0.
inline double viscous_time_step(double factor, double h, double nu) {
  return nu > 0.0 ? factor * h * h / nu : std::numeric_limits<double>::infinity();
}

} // namespace wash::sph
