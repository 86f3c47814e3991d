// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void Fast(wash::Particle &p) { p.set_mass(1); }

int main() {
  wash::add_update_kernel(&Fast);
  wash::start();
  // CHECK: registration-after-start.cpp:[[@LINE+1]]:3: error: call to 'wash::add_force' is after the call to 'wash::start'; registrations must run unconditionally, once, before 'wash::start'
  wash::add_force("late", 1);
}
