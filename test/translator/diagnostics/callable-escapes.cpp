// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// The callable is set in main, out of the kernel's sight.
#include <wash/wash.hpp>
#include <functional>

std::function<void(wash::Particle &)> Step;

void Update(wash::Particle &p) {
  // CHECK: callable-escapes.cpp:[[@LINE+1]]:3: error: a particle is passed through 'std::function<void (wash::Particle &)>', which the translator cannot follow; call the function or lambda directly
  Step(p);
  // CHECK: callable-escapes.cpp:[[@LINE+1]]:3: error: a particle is passed through 'std::invoke', which the translator cannot follow
  std::invoke(Step, p);
}

int main() {
  Step = [](wash::Particle &q) { q.set_mass(3); };
  wash::add_update_kernel(&Update);
  wash::start();
}
