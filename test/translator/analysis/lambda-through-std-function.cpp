// RUN: %wash --dump-model %s 2>&1 | FileCheck %s
// Lambdas the analysis follows are not escapes: one called directly, one
// kept in a std::function and called in the kernel, one given to an
// algorithm.
#include <wash/wash.hpp>
#include <algorithm>
#include <functional>

void Force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  auto direct = [&] { p.set_mass(1); };
  direct();
  std::function<void()> held = [&p] { p.set_density(2); };
  held();
  double sum = 0;
  std::for_each(ns.begin(), ns.end(), [&](const wash::Particle &n) { sum += n.get_mass(); });
  p.set_force_scalar("s", sum);
}

int main() {
  wash::add_force("s", 1);
  wash::add_force_kernel(&Force);
  wash::start();
}
// CHECK-NOT: error:
// CHECK: 0: force Force
// CHECK-NEXT: own-reads: -
// CHECK-NEXT: own-writes: density mass s
// CHECK: neighbour-reads: mass
