// A void kernel is listed in order, touches no particle, and does not end a
// neighbour search (it cannot move particles).
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
#include <wash/wash.hpp>
#include <vector>

void A(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_density(ns.size()); }
void Tick() { wash::set_variable("t", wash::get_variable("t") + 1.0); }
void B(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_force_scalar("b", ns.empty() ? 0.0 : ns[0].get_density() * wash::get_variable("t"));
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_variable("t", 0.0);
  wash::add_force_kernel(&A);
  wash::add_void_kernel(&Tick);
  wash::add_force_kernel(&B);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK: 0: force A
// CHECK: 1: void Tick
// CHECK-NEXT: own-reads: -
// CHECK-NEXT: own-writes: -
// CHECK: 2: force B
// CHECK: neighbour-searches
// CHECK-NEXT: 0: A B
