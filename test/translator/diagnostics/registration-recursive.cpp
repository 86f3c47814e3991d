// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void Fast(wash::Particle &p) { p.set_mass(1); }

void registerMany(int n) {
  // CHECK: registration-recursive.cpp:[[@LINE+1]]:3: error: call to 'wash::add_update_kernel' is in 'registerMany', which calls itself recursively; registrations must run unconditionally, once, before 'wash::start'
  wash::add_update_kernel(&Fast);
  if (n > 0)
    registerMany(n - 1);
}

int main() {
  registerMany(3);
  wash::start();
}
