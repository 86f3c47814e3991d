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

/// With g++ on x86-64, gas_density_compute and gas_forces_compute are
/// compiled twice, for AVX2 (four doubles a vector) and for any x86-64 (two),
/// and the program runs the one its processor supports (chosen when it
/// starts). Separate multiplications and additions either way (no FMA:
/// -ffp-contract=off), so the same bits. Defining WASH_SPH_VECTOR_CLONES
/// empty compiles them once, for the compiler's target.
#ifndef WASH_SPH_VECTOR_CLONES
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define WASH_SPH_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define WASH_SPH_VECTOR_CLONES
#endif
#endif

/// A block of vectors, one component a row (a column per pair): the layout a
/// vectorised loop reads and writes. Left uninitialised, unlike Vec arrays.
template <int N, int D> struct VectorBlock {
  double c[D][N];
  wash::ParticleVec get(int k) const {
    wash::ParticleVec v;
    for (int i = 0; i < D; i++)
      *(v[i]) = c[i][k];
    return v;
  }
  void set(int k, const wash::ParticleVec &v) {
    for (int i = 0; i < D; i++)
      c[i][k] = v.at(i);
  }
};

/// Component i of a curl: a vector in 3D, a number in 2D.
inline double curl_component(const wash::Vec<double, 3> &curl, int i) { return curl.at(i); }
inline double curl_component(double curl, int) { return curl; }
inline void add_to_curl_component(wash::Vec<double, 3> &curl, int i, double x) { *(curl[i]) += x; }
inline void add_to_curl_component(double &curl, int, double x) { curl += x; }

/// gas_density's pair terms for a block of neighbours, gathered in list
/// order, then computed pair by pair with no dependence between pairs
/// (gas_density_compute: a loop the compiler vectorises, two or four square
/// roots and divisions at a time) and summed in list order (gas_density_sum).
/// Each term is the same expression as in one loop over the list, and the
/// sums keep its order: the same bits.
struct DensityBlock {
  static constexpr int size = 32, dims = wash::ParticleVec::dimension;
  using Curl = decltype(cross(wash::ParticleVec{}, wash::ParticleVec{}));
  static constexpr int curlDims = dims == 3 ? 3 : 1;
  double h;
  VectorBlock<size, dims> d, dv; // gathered
  double m[size];
  double kept[size], mW[size], mDiv[size]; // kept: 1 or 0, a double so that the loop vectorises
  double curl[curlDims][size];
  int count = 0;
};

/// DensityBlock's pair terms, b.count of them.
WASH_SPH_VECTOR_CLONES inline void gas_density_compute(DensityBlock &b) {
  const double h = b.h;
  for (int k = 0; k < b.count; k++) {
    const wash::ParticleVec d = b.d.get(k), dv = b.dv.get(k);
    const double r = d.magnitude(), m = b.m[k];
    b.kept[k] = r >= wendland_c2::support * h || r <= 0.0 ? 0.0 : 1.0;
    b.mW[k] = m * wendland_c2::W(r, h);
    const wash::ParticleVec gradW = gradient(d, r, wendland_c2::dWdr(r, h));
    b.mDiv[k] = m * dv.dot(gradW);
    const DensityBlock::Curl curl = cross(dv, gradW) * m;
    for (int i = 0; i < DensityBlock::curlDims; i++)
      b.curl[i][k] = curl_component(curl, i);
  }
}

/// Adds DensityBlock's pair terms to the sums, in list order; empties it.
inline void gas_density_sum(DensityBlock &b, double &rho, double &div, DensityBlock::Curl &curl) {
  gas_density_compute(b);
  for (int k = 0; k < b.count; k++) {
    if (b.kept[k] == 0.0)
      continue;
    rho += b.mW[k];
    div -= b.mDiv[k];
    for (int i = 0; i < DensityBlock::curlDims; i++)
      add_to_curl_component(curl, i, b.curl[i][k]);
  }
  b.count = 0;
}

/// Summation density (the particle's own weight scaled by 1 - selfCorrection),
/// pressure, and the Balsara (1995) switch from the velocity divergence and
/// curl. The pair terms are computed a block of neighbours at a time
/// (DensityBlock).
inline void gas_density(wash::Particle &p, const std::vector<wash::Particle> &neighbours,
                        const GasScheme &s, double selfCorrection) {
  const double h = p.get_smoothing_length();
  const wash::ParticleVec pos = p.get_pos(), vel = p.get_vel();
  double rho = (1.0 - selfCorrection) * p.get_mass() * wendland_c2::W(0.0, h);
  double div = 0.0;
  decltype(cross(vel, vel)) curl{};
  DensityBlock b;
  b.h = h;
  for (const auto &n : neighbours) {
    const int k = b.count;
    b.d.set(k, pos - n.get_pos());
    b.dv.set(k, vel - n.get_vel());
    b.m[k] = n.get_mass();
    if (++b.count == DensityBlock::size)
      gas_density_sum(b, rho, div, curl);
  }
  gas_density_sum(b, rho, div, curl);
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

/// The pair terms of gas_forces for a block of neighbours, gathered in list
/// order, then computed pair by pair with no dependence between pairs
/// (gas_forces_compute: a loop the compiler vectorises, two or four divisions
/// and square roots at a time) and summed in list order (gas_forces_sum).
/// Each term is the same expression as in one loop over the list, and the
/// sums keep its order: the same bits.
struct ForcesBlock {
  static constexpr int size = 32, dims = wash::ParticleVec::dimension;
  // gathered: the particle's own values and, per pair, the neighbour's
  double hi, rhoi, Pi, ci, ui, fi, normi, Pi_rho2;
  VectorBlock<size, dims> d, dv;
  double hj[size], m[size], Pj[size], cj[size], uj[size], normj[size], Pj_rho2[size], rhoj[size],
      fj[size];
  // computed
  VectorBlock<size, dims> acc;
  double kept[size]; // 1 or 0: a double, so that the loop vectorises
  double energy[size], conduction[size], signal[size];
  int count = 0;
};

/// ForcesBlock's pair terms, b.count of them.
WASH_SPH_VECTOR_CLONES inline void gas_forces_compute(ForcesBlock &b, const GasScheme &s) {
  const double hi = b.hi, rhoi = b.rhoi, Pi = b.Pi, ci = b.ci, ui = b.ui, fi = b.fi;
  const double normi = b.normi, Pi_rho2 = b.Pi_rho2;
  const double alpha = s.alpha, beta = s.beta, alphaConductivity = s.alphaConductivity;
  const double searchSupport = s.searchSupport, pairReach = s.pairReach;
  const bool gather = s.searchRule == wash::Support::Gather,
             symmetric = s.searchRule == wash::Support::Symmetric;
  for (int k = 0; k < b.count; k++) {
    const wash::ParticleVec d = b.d.get(k), dv = b.dv.get(k);
    const double r = d.magnitude(), hj = b.hj[k], m = b.m[k], Pj = b.Pj[k], cj = b.cj[k];
    // Both particles of a pair must add the same pair terms, which conserves
    // momentum and energy: the symmetric rule lists i and j in each other's
    // lists (and pairReach cuts both alike); under the gather rule a pair
    // interacts only if each particle is in the other's search sphere.
    b.kept[k] = r <= 0.0 || (gather && d.dot(d) > (searchSupport * hj) * (searchSupport * hj)) ||
                        (symmetric && r > pairReach * std::min(hi, hj))
                    ? 0.0
                    : 1.0;
    const double dWij =
        0.5 * (wendland_c2_dWdr(r, hi, normi) + wendland_c2_dWdr(r, hj, b.normj[k]));
    const wash::ParticleVec gradW = gradient(d, r, dWij);
    const double vr = dv.dot(d), rhoij = 0.5 * (rhoi + b.rhoj[k]);
    const double hij = 0.5 * (hi + hj), mu = monaghan_mu(hij, vr, r);
    const double balsara = 0.5 * (fi + b.fj[k]);
    // approaching (vr < 0): viscosity
    const double viscosity =
        vr < 0.0 ? monaghan_viscosity(alpha, beta, ci, cj, mu, rhoij, balsara) : 0.0;
    b.signal[k] = signal_velocity(ci, cj, vr, r);
    b.acc.set(k, gradW * (m * (Pi_rho2 + b.Pj_rho2[k] + viscosity))); // momentum_factor
    b.energy[k] = m * (Pi_rho2 + 0.5 * viscosity) * dv.dot(gradW);   // energy_factor
    // conduction: u diffuses down its gradient at speed sqrt(|P_i - P_j| / rho)
    b.conduction[k] = price_conductivity(m, alphaConductivity, Pi, Pj, ui, b.uj[k], rhoij, dWij);
  }
}

/// Adds ForcesBlock's pair terms to the sums, in list order; empties it.
inline void gas_forces_sum(ForcesBlock &b, const GasScheme &s, wash::ParticleVec &acc,
                           double &energyRate, double &vsig) {
  gas_forces_compute(b, s);
  for (int k = 0; k < b.count; k++) {
    if (b.kept[k] == 0.0)
      continue;
    vsig = std::max(vsig, b.signal[k]);
    acc -= b.acc.get(k);
    energyRate += b.energy[k];
    energyRate += b.conduction[k];
  }
  b.count = 0;
}

/// Pressure and viscous accelerations, du/dt (with conduction), and the
/// particle's Courant time step. The neighbour's terms of one particle alone
/// (its kernel-gradient norm, P_j / rho_j^2, sound speed, energy) are written
/// apart so that the translator hoists them out of the pair loop; the pair
/// terms are computed a block of neighbours at a time (ForcesBlock).
inline void gas_forces(wash::Particle &p, const std::vector<wash::Particle> &neighbours,
                       const GasScheme &s) {
  const wash::ParticleVec pos = p.get_pos(), vel = p.get_vel();
  ForcesBlock b;
  const double hi = p.get_smoothing_length(), rhoi = p.get_density();
  const double Pi = p.get_force_scalar("pressure"), ci = ideal_gas_sound_speed(s.gamma, Pi, rhoi);
  b.hi = hi;
  b.rhoi = rhoi;
  b.Pi = Pi;
  b.ci = ci;
  b.ui = ideal_gas_energy(s.gamma, Pi, rhoi);
  b.fi = p.get_force_scalar("balsara");
  b.normi = wendland_c2_gradient_norm(hi);
  b.Pi_rho2 = Pi / (rhoi * rhoi);
  wash::ParticleVec acc{};
  double energyRate = 0.0, vsig = ci;
  for (const auto &n : neighbours) {
    const int k = b.count;
    const double rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
    b.d.set(k, pos - n.get_pos());
    b.dv.set(k, vel - n.get_vel());
    b.hj[k] = n.get_smoothing_length();
    b.m[k] = n.get_mass();
    b.rhoj[k] = rhoj;
    b.Pj[k] = Pj;
    b.cj[k] = ideal_gas_sound_speed(s.gamma, Pj, rhoj);
    b.uj[k] = ideal_gas_energy(s.gamma, Pj, rhoj);
    b.normj[k] = wendland_c2_gradient_norm(n.get_smoothing_length());
    b.Pj_rho2[k] = Pj / (rhoj * rhoj);
    b.fj[k] = n.get_force_scalar("balsara");
    if (++b.count == ForcesBlock::size)
      gas_forces_sum(b, s, acc, energyRate, vsig);
  }
  gas_forces_sum(b, s, acc, energyRate, vsig);
  p.set_acc(acc);
  p.set_force_scalar("energy_rate", energyRate);
  p.set_force_scalar("time_step", courant_time_step(s.courant, hi, vsig));
}

} // namespace wash::sph
