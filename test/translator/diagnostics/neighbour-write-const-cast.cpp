// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void kernel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  for (const auto &n : ns)
    // CHECK: neighbour-write-const-cast.cpp:[[@LINE+1]]:37: error: 'set_vel' writes to a neighbour particle; neighbours are read-only
    const_cast<wash::Particle &>(n).set_vel(p.get_vel());
}

int main() {
  wash::add_force_kernel(&kernel);
  wash::start();
}
