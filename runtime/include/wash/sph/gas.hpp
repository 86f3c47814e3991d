//===- wash/sph/gas.hpp - a standard SPH scheme for ideal gas ---*- C++ -*-===//
//
// The compressible scheme of SPH-EXA (Cabezon et al. 2017) that
// examples/sedov and examples/noh run: Wendland C2 (support 2h), summation
// density, the Balsara switch, Monaghan (1992) viscosity with beta, Price
// (2008) conductivity, the internal energy equation and a Courant time step
// from Monaghan's signal velocity. Two force kernels call gas_density and
// gas_forces. It uses the scene's forces
//   "pressure", "energy", "balsara", "energy_rate", "time_step" (scalars),
// registered with wash::add_force. See docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/sph/dissipation.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/time_step.hpp>
#include <wash/wash.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wash::sph {

struct GasScheme {
  double gamma = 5.0 / 3.0; ///< adiabatic index
  double alpha = 1.0;       ///< Monaghan viscosity
  double beta = 1.0;
  double alphaConductivity = 0.3; ///< Price conductivity
  double courant = 0.3;
  /// The neighbour rule main sets: set_smoothing_length_support(searchSupport,
  /// searchRule). Symmetric with support 2 lists exactly the pairs within
  /// 2 max(h_i, h_j), those the Wendland C2 kernel of either particle reaches.
  double searchSupport = 2.0;
  wash::Support searchRule = wash::Support::Symmetric;
  /// Under the symmetric rule a pair interacts only within
  /// pairReach * min(h_i, h_j) (symmetric in i and j, so momentum and energy
  /// stay conserved): across a strong jump in h the larger kernel reaches
  /// particles the smaller one is far from, and those pairs made Sedov's
  /// density L1 1.4 % worse at 30^3 (docs/validation.md). 2.5 is the pair set
  /// the scheme's parameters were tuned with (the gather search within 2.5 h
  /// from both sides); infinity keeps every pair of the list.
  double pairReach = 2.5;
};

/// The fraction of its own kernel weight a particle leaves out of its density
/// (Dehnen & Aly 2012 correct the bias of Wendland kernels this way), chosen
/// so that a square (cubic) lattice of spacing dx and density rho0 with
/// smoothing length h sums to rho0 exactly: gas_density's selfCorrection.
template <int D = wash::dimensions>
double wendland_c2_self_correction(double dx, double h, double rho0) {
  static_assert(D == 2 || D == 3);
  const int reach = int(std::ceil(wendland_c2::support * h / dx));
  double lattice = 0.0, mass = 0.0;
  if constexpr (D == 3) {
    mass = rho0 * dx * dx * dx;
    for (int k = -reach; k <= reach; k++)
      for (int j = -reach; j <= reach; j++)
        for (int i = -reach; i <= reach; i++)
          lattice += mass * wendland_c2::W<3>(dx * std::sqrt(double(i * i + j * j + k * k)), h);
  } else {
    mass = rho0 * dx * dx;
    for (int j = -reach; j <= reach; j++)
      for (int i = -reach; i <= reach; i++)
        lattice += mass * wendland_c2::W<2>(dx * std::sqrt(double(i * i + j * j)), h);
  }
  return (lattice - rho0) / (mass * wendland_c2::W<D>(0.0, h));
}

/// The smoothing length for the next step, hFactor (m / rho)^(1/D), kept
/// within [hMin, hMax].
inline void gas_smoothing_length(wash::Particle &p, double hFactor, double hMin, double hMax) {
  const double volume = p.get_mass() / p.get_density();
  double h = hFactor * (wash::dimensions == 3 ? std::cbrt(volume) : std::sqrt(volume));
  p.set_smoothing_length(std::min(std::max(h, hMin), hMax));
}

/// Summation density (the particle's own weight scaled by 1 - selfCorrection),
/// pressure, and the Balsara (1995) switch from the velocity divergence and curl.
inline void gas_density(wash::Particle &p, const std::vector<wash::Particle> &neighbours,
                        const GasScheme &s, double selfCorrection) {
  const double h = p.get_smoothing_length();
  const wash::ParticleVec pos = p.get_pos(), vel = p.get_vel();
  double rho = (1.0 - selfCorrection) * p.get_mass() * wendland_c2::W(0.0, h);
  double div = 0.0;
  decltype(cross(vel, vel)) curl{};
  for (const auto &n : neighbours) {
    wash::ParticleVec d = pos - n.get_pos();
    double r = d.magnitude();
    if (r >= wendland_c2::support * h || r <= 0.0)
      continue;
    rho += n.get_mass() * wendland_c2::W(r, h);
    wash::ParticleVec gradW = gradient(d, r, wendland_c2::dWdr(r, h));
    wash::ParticleVec dv = vel - n.get_vel();
    div -= n.get_mass() * dv.dot(gradW);
    curl += cross(dv, gradW) * n.get_mass();
  }
  const double energy = p.get_force_scalar("energy");
  const double pressure = ideal_gas_pressure(s.gamma, rho, energy);
  div /= rho;
  const double curlMagnitude = curl_magnitude(curl) / rho;
  p.set_density(rho);
  p.set_force_scalar("pressure", pressure);
  p.set_force_scalar("balsara", balsara_switch(div, curlMagnitude,
                                               ideal_gas_sound_speed(s.gamma, pressure, rho), h));
}

/// wendland_c2::dWdr's factor of h alone, -105 / (16 pi h^4) in 3D: a
/// function of one particle's h, which the translator computes once per
/// neighbour rather than once per pair (non-template, so that it can).
inline double wendland_c2_gradient_norm(double h) {
  return wash::dimensions == 2 ? -35.0 / (4.0 * PI * h * h * h)
                               : -105.0 / (16.0 * PI * h * h * h * h);
}

/// wendland_c2::dWdr(r, h) bit for bit, given norm =
/// wendland_c2_gradient_norm(h): the same operations in the same order.
inline double wendland_c2_dWdr(double r, double h, double norm) {
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q;
  return norm * q * s * s * s;
}

/// Pressure and viscous accelerations, du/dt (with conduction), and the
/// particle's Courant time step. The neighbour's terms of one particle alone
/// (its kernel-gradient norm, P_j / rho_j^2) are written apart so that the
/// translator hoists them out of the pair loop; the pair terms are those of
/// momentum_factor and wendland_c2::dWdr, bit for bit.
inline void gas_forces(wash::Particle &p, const std::vector<wash::Particle> &neighbours,
                       const GasScheme &s) {
  const wash::ParticleVec pos = p.get_pos(), vel = p.get_vel();
  const double hi = p.get_smoothing_length(), rhoi = p.get_density();
  const double Pi = p.get_force_scalar("pressure"), ci = ideal_gas_sound_speed(s.gamma, Pi, rhoi);
  const double ui = ideal_gas_energy(s.gamma, Pi, rhoi), fi = p.get_force_scalar("balsara");
  const double normi = wendland_c2_gradient_norm(hi), Pi_rho2 = Pi / (rhoi * rhoi);
  wash::ParticleVec acc{};
  double energyRate = 0.0, vsig = ci;
  for (const auto &n : neighbours) {
    wash::ParticleVec d = pos - n.get_pos();
    const double r = d.magnitude(), hj = n.get_smoothing_length();
    // Both particles of a pair must add the same pair terms, which conserves
    // momentum and energy: the symmetric rule lists i and j in each other's
    // lists (and pairReach cuts both alike); under the gather rule a pair
    // interacts only if each particle is in the other's search sphere.
    if (r <= 0.0 || (s.searchRule == wash::Support::Gather &&
                     d.dot(d) > (s.searchSupport * hj) * (s.searchSupport * hj)))
      continue;
    if (s.searchRule == wash::Support::Symmetric && r > s.pairReach * std::min(hi, hj))
      continue;
    const double m = n.get_mass(), rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
    const double cj = ideal_gas_sound_speed(s.gamma, Pj, rhoj);
    const double uj = ideal_gas_energy(s.gamma, Pj, rhoj);
    const double normj = wendland_c2_gradient_norm(n.get_smoothing_length()), Pj_rho2 = Pj / (rhoj * rhoj);
    const double dWij = 0.5 * (wendland_c2_dWdr(r, hi, normi) + wendland_c2_dWdr(r, hj, normj));
    const wash::ParticleVec gradW = gradient(d, r, dWij), dv = vel - n.get_vel();
    const double vr = dv.dot(d), rhoij = 0.5 * (rhoi + rhoj);
    double viscosity = 0.0;
    if (vr < 0.0) { // approaching
      double hij = 0.5 * (hi + hj), mu = monaghan_mu(hij, vr, r);
      double balsara = 0.5 * (fi + n.get_force_scalar("balsara"));
      viscosity = monaghan_viscosity(s.alpha, s.beta, ci, cj, mu, rhoij, balsara);
    }
    vsig = std::max(vsig, signal_velocity(ci, cj, vr, r));
    acc -= gradW * (m * (Pi_rho2 + Pj_rho2 + viscosity)); // momentum_factor
    energyRate += m * (Pi_rho2 + 0.5 * viscosity) * dv.dot(gradW); // energy_factor
    // conduction: u diffuses down its gradient at speed sqrt(|P_i - P_j| / rho)
    energyRate += price_conductivity(m, s.alphaConductivity, Pi, Pj, ui, uj, rhoij, dWij);
  }
  p.set_acc(acc);
  p.set_force_scalar("energy_rate", energyRate);
  p.set_force_scalar("time_step", courant_time_step(s.courant, hi, vsig));
}

} // namespace wash::sph
