// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_mass(1); }

int main() {
  // CHECK: registration-indirect.cpp:[[@LINE+1]]:22: error: 'wash::add_update_kernel' is used other than by a direct call; the translator cannot see what it registers
  auto *reg = &wash::add_update_kernel;
  reg(&update, "", wash::CallSite::current());
  wash::start();
}
