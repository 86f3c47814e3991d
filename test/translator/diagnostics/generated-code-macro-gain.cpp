// The compile gate catches a rewrite that loses a macro argument: the
// setter's value uses the user's macro GAIN. Wherever the translator's
// rewrite goes wrong, the error is at the user's line, nothing is written.
// (If the rewrite is fixed, the program translates: the RUN lines below
// then fail and this test moves to emit/.)
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

#define GAIN 2.0

void Grow(wash::Particle &p) {
  // CHECK: generated-code-macro-gain.cpp:[[@LINE+1]]:{{[0-9]+}}: error: the generated code does not compile here: expected expression
  p.set_mass(p.get_mass() * GAIN);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Grow);
  wash::set_max_iterations(1);
  wash::start();
}
