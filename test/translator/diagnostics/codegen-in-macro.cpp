// A particle access written inside a macro cannot be rewritten in place.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

#define SPEED(p) (p).get_vel().magnitude()

void Slow(wash::Particle& p) {
  // CHECK: codegen-in-macro.cpp:[[@LINE+1]]:20: error: a particle access or particle type inside a macro expansion cannot be rewritten; write it out in the source
  double s = 1.0 + SPEED(p);
  p.set_density(s);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Slow);
  wash::set_max_iterations(1);
  wash::start();
}
