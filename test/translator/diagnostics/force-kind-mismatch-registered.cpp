// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) {
  // CHECK: force-kind-mismatch-registered.cpp:[[@LINE+1]]:16: error: force 'pressure' is a vector but is used as a scalar
  double x = p.get_force_scalar("pressure");
  p.set_density(x);
}

int main() {
  // CHECK: force-kind-mismatch-registered.cpp:[[@LINE+1]]:19: note: 'pressure' registered here
  wash::add_force("pressure", 2);
  wash::add_update_kernel(&update);
  wash::start();
}
