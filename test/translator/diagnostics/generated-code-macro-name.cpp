// The compile gate catches a user macro named like a name the generated code
// uses (wash_gen::P, the particle columns): the error is in the user's file,
// nothing is written.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

#define P 1

void Grow(wash::Particle &p) {
  // CHECK: generated-code-macro-name.cpp:[[@LINE+1]]:{{[0-9]+}}: error: the generated code does not compile here:
  p.set_mass(p.get_mass() * 2.0);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Grow);
  wash::set_max_iterations(1);
  wash::start();
}
