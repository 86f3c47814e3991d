// The compile gate, for an error in purely generated code (no #line to the
// user's file): a user macro named like a variable of the generated driver
// (`self`, each kernel's particle) breaks the driver's section of each
// kernel; each error is reported at that kernel's registration, with the
// generated file and line. Nothing is written.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

#define self 0

void Grow(wash::Particle &p) { p.set_mass(p.get_mass() * 2.0); }

void Sum(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  double m = 0;
  for (const wash::Particle &q : neighbours)
    m += q.get_mass();
  p.set_density(m);
}

int main() {
  wash::set_influence_radius(0.1);
  // CHECK: generated-code-in-driver.cpp:[[@LINE+1]]:3: error: the generated code does not compile here: {{.*}} (in the generated generated-code-in-driver.serial.cpp:{{[0-9]+}})
  wash::add_update_kernel(&Grow);
  // CHECK: generated-code-in-driver.cpp:[[@LINE+1]]:3: error: the generated code does not compile here: {{.*}} (in the generated generated-code-in-driver.serial.cpp:{{[0-9]+}})
  wash::add_force_kernel(&Sum);
  wash::set_max_iterations(1);
  wash::start();
}
