//===- wash/sph/leapfrog.hpp - kick-drift-kick leapfrog ---------*- C++ -*-===//
//
// Kick-drift-kick leapfrog (Verlet) for velocity and internal energy, in two
// halves around the force kernels. It uses the scene's forces
//   "energy", "energy_rate" (scalars) and "energy_half" (scalar),
//   "vel_half" (a vector),
// which the scene registers with wash::add_force. See docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/wash.hpp>

namespace wash::sph {

/// First half kick and drift: vel and energy become the predicted full-step
/// values the force kernels see; the half-step values wait for leapfrog_kick.
inline void leapfrog_kick_drift(wash::Particle &p, double dt) {
  wash::ParticleVec velHalf = p.get_vel() + p.get_acc() * (0.5 * dt);
  double energyHalf = p.get_force_scalar("energy") + p.get_force_scalar("energy_rate") * (0.5 * dt);
  p.set_pos(p.get_pos() + velHalf * dt);
  p.set_force_vector("vel_half", velHalf);
  p.set_force_scalar("energy_half", energyHalf);
  p.set_vel(velHalf + p.get_acc() * (0.5 * dt));
  p.set_force_scalar("energy", energyHalf + p.get_force_scalar("energy_rate") * (0.5 * dt));
}

/// Second half kick: the state at the end of the step. Returns the energy.
inline double leapfrog_kick(wash::Particle &p, double dt) {
  p.set_vel(p.get_force_vector("vel_half") + p.get_acc() * (0.5 * dt));
  double energy =
      p.get_force_scalar("energy_half") + p.get_force_scalar("energy_rate") * (0.5 * dt);
  p.set_force_scalar("energy", energy);
  return energy;
}

} // namespace wash::sph
