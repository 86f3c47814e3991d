// A per-particle kernel may read global variables but not set them.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

void Count(wash::Particle &p) {
  // CHECK: variable-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Count' sets a global variable; it runs once per particle, so only main, init kernels and void kernels may set variables
  wash::set_variable("n", wash::get_variable("n") + p.get_density());
}

void Tick() { wash::set_variable("ticks", wash::get_variable("ticks") + 1.0); }

int main() {
  wash::add_variable("n", 0.0);
  wash::add_variable("ticks", 0.0);
  wash::add_void_kernel(&Tick);
  wash::add_update_kernel(&Count);
  wash::start();
}
