// The compile gate, for an error in purely generated code (no #line to the
// user's file): a user's own namespace wash_gen, with a variable named like
// the driver's backend, breaks the driver. An error in a kernel's section of
// the driver is reported at that kernel's registration, one elsewhere at the
// simulation's first line, each with the generated file and line. Nothing is
// written.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
// CHECK-DAG: generated-code-in-driver.cpp:1:1: error: the generated code does not compile here: reference to 'backend' is ambiguous (in the generated generated-code-in-driver.serial.cpp:{{[0-9]+}})
#include <wash/wash.hpp>

namespace wash_gen {
int backend = 0;
}

void Grow(wash::Particle &p) { p.set_mass(p.get_mass() * 2.0); }

void Sum(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  double m = 0;
  for (const wash::Particle &q : neighbours)
    m += q.get_mass();
  p.set_density(m);
}

int main() {
  wash::set_influence_radius(0.1);
  // CHECK-DAG: generated-code-in-driver.cpp:[[@LINE+1]]:3: error: the generated code does not compile here: {{.*}} (in the generated generated-code-in-driver.serial.cpp:{{[0-9]+}})
  wash::add_update_kernel(&Grow);
  // CHECK-DAG: generated-code-in-driver.cpp:[[@LINE+1]]:3: error: the generated code does not compile here: {{.*}} (in the generated generated-code-in-driver.serial.cpp:{{[0-9]+}})
  wash::add_force_kernel(&Sum);
  wash::set_max_iterations(1);
  wash::start();
}
