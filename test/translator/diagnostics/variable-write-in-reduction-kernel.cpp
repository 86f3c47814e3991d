// A reduction kernel runs once per particle too (on MPI, on each rank for its
// own particles): it may not set a variable any more than an update kernel.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

double Heaviest(const wash::Particle &p) {
  // CHECK: variable-write-in-reduction-kernel.cpp:[[@LINE+1]]:3: error: reduction kernel 'Heaviest' sets a global variable; it runs once per particle, so only main, init kernels and void kernels may set variables
  wash::set_variable("count", wash::get_variable("count") + 1.0);
  return p.get_mass();
}

int main() {
  wash::add_variable("count", 0.0);
  wash::add_variable("heaviest", 0.0);
  wash::add_reduction_kernel(&Heaviest, wash::Reduction::Max, "heaviest");
  wash::start();
}
