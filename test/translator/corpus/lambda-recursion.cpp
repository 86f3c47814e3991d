// A generic lambda calling itself: recursion, reported, not a hang.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>
void u(wash::Particle &p) {
  auto rec = [](auto &self, const wash::Particle &q, int n) -> double {
    return n == 0 ? q.get_mass() : self(self, q, n - 1);
  };
  p.set_density(rec(rec, p, 3));
}
int main() { wash::add_update_kernel(&u); wash::start(); }
// CHECK: lambda-recursion.cpp:6:36: error: recursive call to
