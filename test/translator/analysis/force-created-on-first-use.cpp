// A force never registered is created, as the kind its first use says, with
// a warning at that first use (init kernels run first).
// RUN: %wash --dump-model %s 2> %t.err | FileCheck %s
// RUN: FileCheck %s --check-prefix=WARN < %t.err
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_force_vector("drift", p.get_vel()); }

void init() {
  auto &p = wash::create_particle(1, 1, 0.1, {0.0, 0.0}, {0.0, 0.0});
  // WARN: force-created-on-first-use.cpp:[[@LINE+1]]:5: warning: force 'drift' is used but never registered; it is created as a vector
  p.set_force_vector("drift", {1.0, 0.0});
}

int main() {
  wash::add_update_kernel(&update);
  wash::add_init_kernel(&init);
  wash::start();
}
// CHECK: drift: created vector2 live output-only @12:5
// WARN-NOT: warning:
