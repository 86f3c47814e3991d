// The compile gate catches `using Particle = wash::Particle;`, which the
// rewrite turns into `using Particle = auto;`: the error is at the alias,
// nothing is written.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

// CHECK: generated-code-particle-alias.cpp:[[@LINE+1]]:{{[0-9]+}}: error: the generated code does not compile here: {{.*}}auto{{.*}}
using Particle = wash::Particle;

void Grow(Particle &p) { p.set_mass(p.get_mass() * 2.0); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Grow);
  wash::set_max_iterations(1);
  wash::start();
}
