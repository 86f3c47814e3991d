// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

double odd(const wash::Particle &p, int n);
double even(const wash::Particle &p, int n) { return n == 0 ? p.get_mass() : odd(p, n - 1); }
// CHECK: recursion.cpp:[[@LINE+1]]:66: error: recursive call to 'even' in kernel 'update' hides which particle properties it accesses
double odd(const wash::Particle &p, int n) { return n == 0 ? 0 : even(p, n - 1); }

void update(wash::Particle &p) { p.set_density(even(p, 4)); }

int main() {
  // CHECK: recursion.cpp:[[@LINE+1]]:3: note: kernel 'update' registered here
  wash::add_update_kernel(&update);
  wash::start();
}
