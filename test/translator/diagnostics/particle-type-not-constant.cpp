// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

#include <string>

int main(int argc, char **argv) {
  std::string name = argv[0];
  // CHECK: particle-type-not-constant.cpp:[[@LINE+1]]:27: error: particle type name must be a string literal or a constant the translator can evaluate
  wash::add_particle_type(name);
  wash::start();
}
