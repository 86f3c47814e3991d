// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: particle-type-invalid.cpp:[[@LINE+1]]:27: error: particle type name 'wall type' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)
  wash::add_particle_type("wall type");
  wash::start();
}
