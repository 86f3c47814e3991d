// A per-particle kernel may read the time and the time step but not set the
// step; a force kernel or a helper it calls is rejected too. Void and init
// kernels and main may set it, and a reduction may target "time_step" (which
// is then no unknown variable).
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

#include <vector>

void Halve() { wash::set_time_step(0.5 * wash::get_time_step()); }

void Move(wash::Particle &p) {
  p.set_pos(p.get_pos() + p.get_vel() * wash::get_time_step());
  // CHECK: time-step-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Move' sets the time step; it runs once per particle, so only main, init kernels and void kernels may call wash::set_time_step (a reduction kernel may target 'time_step')
  wash::set_time_step(wash::get_time());
}

void slower(double factor) { wash::set_time_step(factor * wash::get_time_step()); }

void Push(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  p.set_acc(p.get_vel() * double(neighbours.size()));
  // CHECK: time-step-write-in-particle-kernel.cpp:[[@LINE-4]]:30: error: force kernel 'Push' sets the time step; it runs once per particle, so only main, init kernels and void kernels may call wash::set_time_step (a reduction kernel may target 'time_step')
  slower(0.9);
}

double Courant(const wash::Particle &p) { return 0.1 / p.get_vel().magnitude(); }

int main() {
  wash::set_influence_radius(0.1);
  wash::set_time_step(0.01);
  wash::set_end_time(1.0);
  wash::add_reduction_kernel(&Courant, wash::Reduction::Min, "time_step");
  wash::add_void_kernel(&Halve);
  wash::add_update_kernel(&Move);
  wash::add_force_kernel(&Push);
  wash::start();
}
