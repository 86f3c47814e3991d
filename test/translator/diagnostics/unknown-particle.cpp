// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

std::vector<wash::Particle> stash;

void update(wash::Particle &p) {
  // CHECK: unknown-particle.cpp:[[@LINE+1]]:23: error: cannot tell which particle 'get_mass' accesses; kernels may only use their own particle, its neighbours and particles they create
  p.set_mass(stash[0].get_mass());
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
