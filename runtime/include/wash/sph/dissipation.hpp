//===- wash/sph/dissipation.hpp - artificial dissipation terms --*- C++ -*-===//
//
// The pair terms of artificial viscosity, conductivity, density diffusion and
// the XSPH velocity, for a particle i and its neighbour j, with d = x_i - x_j,
// r = |d|, vr = (v_i - v_j) . d. Each is written in the order of operations of
// the examples that use it, so that moving a scene onto the library changes no
// bit of its results. Formulas and references: docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/wash.hpp>

#include <cmath>

namespace wash::sph {

/// Monaghan's mu_ij = h vr / (r^2 + eta^2 h^2), eta^2 = 0.01.
inline double monaghan_mu(double h, double vr, double r) { return h * vr / (r * r + 0.01 * h * h); }

/// Monaghan (1992) artificial viscosity Pi_ij for an approaching pair (vr < 0;
/// 0 otherwise): f (-alpha cbar mu + beta mu^2) / rhobar, cbar = (ci + cj) / 2,
/// with f a switch (Balsara's, or 1).
inline double monaghan_viscosity(double alpha, double beta, double ci, double cj, double mu,
                                 double rhoMean, double factor = 1.0) {
  return factor * (-alpha * 0.5 * (ci + cj) * mu + beta * mu * mu) / rhoMean;
}

/// Balsara (1995) switch: |div v| / (|div v| + |curl v| + 1e-4 c / h).
inline double balsara_switch(double divergence, double curlMagnitude, double c, double h) {
  return std::abs(divergence) / (std::abs(divergence) + curlMagnitude + 1e-4 * c / h);
}

/// The cross product the Balsara switch's curl accumulates: a vector in 3D,
/// the scalar a_x b_y - a_y b_x in 2D.
template <typename V> auto cross(const V &a, const V &b) {
  if constexpr (V::dimension == 3)
    return V{a.at(1) * b.at(2) - a.at(2) * b.at(1), a.at(2) * b.at(0) - a.at(0) * b.at(2),
             a.at(0) * b.at(1) - a.at(1) * b.at(0)};
  else
    return a.at(0) * b.at(1) - a.at(1) * b.at(0);
}

/// |curl|, for either kind of cross product.
inline double curl_magnitude(double curl) { return std::abs(curl); }
template <typename V> double curl_magnitude(const V &curl) { return curl.magnitude(); }

/// Monaghan's signal velocity (1997, beta = 3): ci + cj - 3 vr / r if the pair
/// approaches, else ci + cj.
inline double signal_velocity(double ci, double cj, double vr, double r) {
  return vr < 0.0 ? ci + cj - 3.0 * vr / r : ci + cj;
}

/// Price (2008) artificial conductivity, the pair's du_i/dt:
/// m_j alpha_u sqrt(|Pi - Pj| / rhobar) (ui - uj) / rhobar dW_ij/dr.
inline double price_conductivity(double mj, double alpha, double Pi, double Pj, double ui,
                                 double uj, double rhoMean, double dWdr) {
  return mj * alpha * std::sqrt(std::abs(Pi - Pj) / rhoMean) * (ui - uj) / rhoMean * dWdr;
}

/// delta-SPH density diffusion (Molteni & Colagrossi 2009), the pair's
/// drho_i/dt: 2 delta h c0 (rho_j - rho_i) (x_j - x_i) . grad_i W / r^2 * m_j / rho_j,
/// which is -2 delta h c0 (rho_j - rho_i) (dW/dr / r) m_j / rho_j.
inline double delta_sph_diffusion(double delta, double h, double c0, double rhoi, double rhoj,
                                  double mj, double r, double dWdr) {
  return -2.0 * delta * h * c0 * (rhoj - rhoi) * (dWdr / r) * mj / rhoj;
}

/// XSPH (Monaghan 1989): the pair's term of v_i's correction,
/// eps m_j / rhobar (v_j - v_i) W_ij; the particle moves with v_i + sum.
template <typename V>
V xsph_correction(double eps, double mj, double rhoi, double rhoj, const V &vji, double W) {
  return vji * (eps * mj / (0.5 * (rhoi + rhoj)) * W);
}

/// The symmetric pressure (and viscosity) force factor of Monaghan (1992):
/// a_i -= grad_i W * m_j (Pi / rhoi^2 + Pj / rhoj^2 + Pi_ij).
inline double momentum_factor(double mj, double Pi, double rhoi, double Pj, double rhoj,
                              double viscosity) {
  return mj * (Pi / (rhoi * rhoi) + Pj / (rhoj * rhoj) + viscosity);
}
/// The matching internal energy rate: du_i/dt += m_j (Pi / rhoi^2 + Pi_ij / 2) vij . grad_i W.
inline double energy_factor(double mj, double Pi, double rhoi, double viscosity) {
  return mj * (Pi / (rhoi * rhoi) + 0.5 * viscosity);
}

} // namespace wash::sph
