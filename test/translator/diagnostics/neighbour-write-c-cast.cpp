// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void kernel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  auto &all = (std::vector<wash::Particle> &)ns;
  // CHECK: neighbour-write-c-cast.cpp:[[@LINE+1]]:10: error: 'set_density' writes to a neighbour particle
  all[0].set_density(p.get_density());
}

int main() {
  wash::add_force_kernel(&kernel);
  wash::start();
}
