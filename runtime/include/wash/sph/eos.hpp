//===- wash/sph/eos.hpp - equations of state --------------------*- C++ -*-===//
//
// Pressure from density (and internal energy), the inverse, and the sound
// speed. Formulas and references: docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cmath>

namespace wash::sph {

/// Ideal gas: P = (gamma - 1) rho u.
inline double ideal_gas_pressure(double gamma, double density, double energy) {
  return (gamma - 1.0) * density * energy;
}
/// The specific internal energy of an ideal gas at pressure P and density rho.
inline double ideal_gas_energy(double gamma, double pressure, double density) {
  return pressure / ((gamma - 1.0) * density);
}
/// c = sqrt(gamma P / rho).
inline double ideal_gas_sound_speed(double gamma, double pressure, double density) {
  return std::sqrt(gamma * pressure / density);
}
/// c = sqrt(gamma (gamma - 1) u), the same from the internal energy.
inline double ideal_gas_sound_speed_from_energy(double gamma, double energy) {
  return std::sqrt(gamma * (gamma - 1.0) * energy);
}

/// Tait's equation (Cole 1948; Monaghan 1994) for weakly compressible water:
/// P = B ((rho / rho0)^gamma - 1), B = c0^2 rho0 / gamma.
struct Tait {
  double rho0;        ///< reference density
  double c0;          ///< sound speed at rho0
  double gamma = 7.0; ///< 7 for water

  double stiffness() const { return c0 * c0 * rho0 / gamma; }
  double pressure(double density) const {
    return stiffness() * (std::pow(density / rho0, gamma) - 1.0);
  }
  /// The inverse: rho = rho0 (P / B + 1)^(1 / gamma).
  double density(double pressure) const {
    return rho0 * std::pow(pressure / stiffness() + 1.0, 1.0 / gamma);
  }
  /// c = c0 (rho / rho0)^((gamma - 1) / 2), the slope sqrt(dP/drho).
  double sound_speed(double density) const {
    return c0 * std::pow(density / rho0, 0.5 * (gamma - 1.0));
  }
};

/// The linear (isothermal) weakly compressible law with a background pressure:
/// P = c0^2 (rho - rho0) + Pb.
struct LinearEos {
  double rho0;
  double c0;
  double background = 0.0;

  double pressure(double density) const { return c0 * c0 * (density - rho0) + background; }
  double density(double pressure) const { return rho0 + (pressure - background) / (c0 * c0); }
  double sound_speed(double) const { return c0; }
};

} // namespace wash::sph
