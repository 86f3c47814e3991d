// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

#include <vector>

void force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  // CHECK: set-type-outside-kernel.cpp:[[@LINE+1]]:5: error: 'set_type' in force kernel 'force'; a particle's type is set only by init kernels and by update kernels on their own particle
  p.set_type("wall");
  p.set_density(double(ns.size()));
}

int main() {
  wash::add_particle_type("fluid");
  wash::add_particle_type("wall");
  wash::set_influence_radius(1.0);
  wash::add_force_kernel(&force);
  wash::start();
}
