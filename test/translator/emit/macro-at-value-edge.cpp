// A setter's value that begins or ends with a whole macro expansion is kept
// as written (it used to become `P.mass[p] = ;`); an access inside a macro is
// still refused (codegen-in-macro.cpp).
// RUN: rm -rf %t
// RUN: %wash --backend=serial -o %t %s
// RUN: FileCheck %s < %t/macro-at-value-edge.serial.cpp
// RUN: %cxx_check -I%t %t/macro-at-value-edge.serial.cpp
#include <wash/wash.hpp>
#include <cfloat>
#include <cmath>

#define GAIN 2.0
#define HALF(x) ((x) / 2)

void Step(wash::Particle &p) {
  p.set_mass(p.get_mass() * GAIN);
  p.set_density(M_PI * p.get_density());
  p.set_smoothing_length(p.get_smoothing_length() + DBL_EPSILON);
  p.set_force_scalar("line", __LINE__);
  p.set_force_scalar("half", HALF(3.0));
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("line", 1);
  wash::add_force("half", 1);
  wash::add_update_kernel(&Step);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK:      wash_gen::P.mass[p] = wash_gen::P.mass[p] * GAIN;
// CHECK-NEXT: wash_gen::P.density[p] = M_PI * wash_gen::P.density[p];
// CHECK-NEXT: wash_gen::P.smoothing_length[p] = wash_gen::P.smoothing_length[p] + DBL_EPSILON;
// CHECK-NEXT: wash_gen::P.line[p] = __LINE__;
// CHECK-NEXT: wash_gen::P.half[p] = HALF(3.0);
