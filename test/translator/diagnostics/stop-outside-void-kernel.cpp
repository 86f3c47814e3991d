// Only void kernels may end the run: a per-particle kernel calling wash::stop()
// would stop some MPI ranks and not others.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

void Check(wash::Particle &p) {
  // CHECK: stop-outside-void-kernel.cpp:[[@LINE+2]]:5: error: update kernel 'Check' calls wash::stop(); only void kernels may end the run, so that every rank stops at the same iteration
  if (p.get_density() > 2.0)
    wash::stop();
}

void Clock() {
  if (wash::get_variable("t") > 1.0)
    wash::stop();
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_variable("t", 0.0);
  wash::add_update_kernel(&Check);
  wash::add_void_kernel(&Clock);
  wash::start();
}
