// An error leaves no generated project behind, not even a partial one.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
// CHECK: error: force 'heat' is a scalar but is used as a vector
#include <wash/wash.hpp>

void Heat(wash::Particle& p) {
  p.set_force_scalar("heat", 1.0);
  p.set_vel(p.get_force_vector("heat"));
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
