// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// A force created on first use clashes too (it would redeclare the column).
// RUN: %expect_exit 1 %wash --dump-model %s -- -DCREATED 2>&1 | FileCheck %s --check-prefix=CREATED
#include <wash/wash.hpp>

#ifndef CREATED
int main() {
  wash::add_particle_type("fluid");
  // CHECK: particle-type-name-clash.cpp:[[@LINE+1]]:19: error: force 'type' in a simulation with particle types; its output column would clash with the particles' type column
  wash::add_force("type", 1);
  wash::start();
}
#else
void Mark(wash::Particle &p) {
  // CREATED: particle-type-name-clash.cpp:[[@LINE+1]]:5: error: force 'type' in a simulation with particle types; its output column would clash with the particles' type column
  p.set_force_scalar("type", 1.0);
}

int main() {
  wash::add_particle_type("fluid");
  wash::add_update_kernel(&Mark);
  wash::start();
}
#endif
