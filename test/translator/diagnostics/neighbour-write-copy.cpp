// A Particle is a handle: writing through a copy of a neighbour writes the
// neighbour, including inside a helper.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

// CHECK-DAG: neighbour-write-copy.cpp:[[@LINE+1]]:33: error: 'set_force_scalar' writes to a neighbour particle
void heat(wash::Particle q) { q.set_force_scalar("t", 1.0); }

void kernel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Particle n = ns[0];
  // CHECK-DAG: neighbour-write-copy.cpp:[[@LINE+1]]:5: error: 'set_vel' writes to a neighbour particle
  n.set_vel(p.get_vel());
  heat(ns[1]);
}

int main() {
  wash::add_force_kernel(&kernel);
  wash::start();
}
