// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void Fast(wash::Particle &p) { p.set_mass(1); }

void registerAgain(int argc) {
  int i = 0;
again:
  // CHECK: registration-goto.cpp:[[@LINE+1]]:3: error: call to 'wash::add_update_kernel' is in a function that uses 'goto'; registrations must run unconditionally, once, before 'wash::start'
  wash::add_update_kernel(&Fast);
  if (++i < argc)
    goto again;
}

int main(int argc, char **) {
  registerAgain(argc);
  wash::start();
}
