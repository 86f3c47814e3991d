// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) {
  // CHECK: create-outside-init.cpp:[[@LINE+1]]:3: error: 'wash::create_particle' called from update kernel 'update'; particles can only be created by init kernels
  wash::create_particle(1, 1, 1, p.get_pos(), p.get_vel());
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
