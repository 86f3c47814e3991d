// A kernel's code is rewritten once for every caller, so a name parameter
// that two calls bind to different names cannot be lowered: an error at the
// use, not the default (or either name) for both.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void Bump(wash::Particle &p, const char *const name = "alpha") {
  // CHECK: name-parameter-bound-twice.cpp:[[@LINE+1]]:22: error: force name must be
  p.set_force_scalar(name, 1.0);
}
void Step(wash::Particle &p) {
  Bump(p, "beta");
  Bump(p);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("alpha", 1);
  wash::add_force("beta", 1);
  wash::add_update_kernel(&Step);
  wash::start();
}
