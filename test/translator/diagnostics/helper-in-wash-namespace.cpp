// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// User code in namespace wash was skipped as if it were the API.
#include <wash/wash.hpp>

namespace wash {
void myHelper(Particle &p) { p.set_mass(3); }
double twice(double x) { return 2 * x; } // No particle: fine.
} // namespace wash

void Update(wash::Particle &p) {
  // CHECK: helper-in-wash-namespace.cpp:[[@LINE+1]]:3: error: 'wash::myHelper' receives a particle but is declared in namespace 'wash', which the translator does not follow; move it out of namespace 'wash'
  wash::myHelper(p);
  p.set_density(wash::twice(p.get_mass()));
}

int main() {
  wash::add_update_kernel(&Update);
  wash::start();
}
