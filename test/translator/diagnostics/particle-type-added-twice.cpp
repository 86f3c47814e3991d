// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: particle-type-added-twice.cpp:[[@LINE+3]]:27: error: particle type 'wall' is added more than once
  // CHECK: particle-type-added-twice.cpp:[[@LINE+1]]:27: note: 'wall' registered here
  wash::add_particle_type("wall");
  wash::add_particle_type("wall");
  wash::start();
}
