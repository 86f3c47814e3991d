// C++ leaves the order of a call's arguments unspecified (g++ goes right to
// left), and runs an assignment's right side first: two registrations there
// have no order the translator can read. One registration per operand, or
// operands C++ sequences (a comma, <<), are fine.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

int reg(const char *name) {
  wash::add_force(name, 1);
  return 0;
}
int both(int, int) { return 0; }

void Touch(wash::Particle &p) { p.set_force_scalar("a", p.get_force_scalar("b") + p.get_force_scalar("c") + p.get_force_scalar("d")); }

int main() {
  wash::set_influence_radius(0.5);
  // CHECK: registration-unsequenced.cpp:[[@LINE+1]]:3: error: two operands of this expression register with wash
  both(reg("a"), reg("b"));
  int x = 0;
  // CHECK: registration-unsequenced.cpp:[[@LINE+1]]:7: error: two operands of this expression register with wash
  x = reg("c") + reg("d");
  (void)reg("e"), (void)reg("f");
  both(reg("g"), 1);
  wash::add_update_kernel(&Touch);
  wash::start();
}
