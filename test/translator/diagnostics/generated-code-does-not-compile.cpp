// The compile gate: a kernel may call a member of the neighbour list that
// wash::Particle's std::vector has but the generated neighbour list type
// (wash::backend::Neighbours) lacks. The translator accepts it; the gate
// type-checks the generated code, reports clang's error at the user's line
// and writes nothing. With --no-compile-gate the project is written.
// RUN: rm -rf %t %t.nogate
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
// RUN: %expect_exit 1 %wash --backend=openmp -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
// RUN: %wash --backend=serial -o %t.nogate --no-compile-gate %s
// RUN: test -e %t.nogate/generated-code-does-not-compile.serial.cpp
#include <wash/wash.hpp>

void Sum(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  double m = 0;
  // CHECK: generated-code-does-not-compile.cpp:[[@LINE+1]]:{{[0-9]+}}: error: the generated code does not compile here: no member named 'rbegin' in {{.*}}
  for (auto it = neighbours.rbegin(); it != neighbours.rend(); ++it)
    m += it->get_mass();
  p.set_density(m);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&Sum);
  wash::set_max_iterations(1);
  wash::start();
}
