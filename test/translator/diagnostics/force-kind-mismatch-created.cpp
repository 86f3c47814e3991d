// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void first(wash::Particle &p) {
  // CHECK: force-kind-mismatch-created.cpp:[[@LINE+2]]:5: error: force 'heat' is a scalar but is used as a vector
  // CHECK: force-kind-mismatch-created.cpp:[[@LINE+4]]:5: note: 'heat' first used as a scalar here
  p.set_force_vector("heat", p.get_vel());
}
void second(wash::Particle &p) {
  p.set_force_scalar("heat", 1.0);
}

int main() {
  wash::add_update_kernel(&second);
  wash::add_update_kernel(&first);
  wash::start();
}
