// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_vel({}); }

int main() {
  // CHECK: particle-type-unknown-untyped.cpp:[[@LINE+1]]:36: error: particle type 'fluid' is never added with wash::add_particle_type (this simulation adds no particle type)
  wash::add_update_kernel(&update, "fluid");
  wash::start();
}
