// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>
#include <string>

void update(wash::Particle &p) {
  std::string name = "heat";
  // CHECK: force-name-not-constant.cpp:[[@LINE+1]]:22: error: force name must be a string literal or a constant the translator can evaluate
  p.set_force_scalar(name, 1.0);
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
