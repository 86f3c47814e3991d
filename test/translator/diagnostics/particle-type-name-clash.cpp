// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  wash::add_particle_type("fluid");
  // CHECK: particle-type-name-clash.cpp:[[@LINE+1]]:19: error: force 'type' in a simulation with particle types; its output column would clash with the particles' type column
  wash::add_force("type", 1);
  wash::start();
}
