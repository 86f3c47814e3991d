// A static local's initialiser runs the first time its function is called
// only: registering there registers once however often the helper runs.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

int reg(const char *name) {
  wash::add_force(name, 1);
  return 0;
}

void setup() {
  // CHECK: registration-in-static-init.cpp:[[@LINE+1]]:14: error: the initialiser of static variable 'once' registers with wash
  static int once = reg("heat");
  int every = reg("cold");
  (void)once, (void)every;
}

void Touch(wash::Particle &p) { p.set_force_scalar("heat", p.get_force_scalar("cold")); }

int main() {
  wash::set_influence_radius(0.5);
  setup();
  wash::add_update_kernel(&Touch);
  wash::start();
}
