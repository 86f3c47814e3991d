// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// A helper held in a std::function: the write it makes was dropped.
#include <wash/wash.hpp>
#include <functional>

void Helper(wash::Particle &p) { p.set_mass(3); }

void Update(wash::Particle &p) {
  // CHECK: function-escapes.cpp:[[@LINE+1]]:45: error: 'Helper' takes a particle and is used other than by a direct call; the translator cannot follow the calls made through it
  std::function<void(wash::Particle &)> f = Helper;
  // CHECK: function-escapes.cpp:[[@LINE+1]]:3: error: a particle is passed through 'std::function<void (wash::Particle &)>', which the translator cannot follow; call the function or lambda directly
  f(p);
}

int main() {
  wash::add_update_kernel(&Update);
  wash::start();
}
