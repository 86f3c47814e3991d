// A random engine kept in a global and drawn from per particle: the draws
// depend on the order particles run in.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <random>

std::mt19937 Gen(42);
std::default_random_engine Engines[2];

double jitter(std::mt19937 &g) {
  std::normal_distribution<double> noise(0.0, 1e-6);
  return noise(g); // Through the parameter: reported where Gen is passed.
}

void Shake(wash::Particle &p) {
  // CHECK: global-engine-in-particle-kernel.cpp:[[@LINE+2]]:57: error: update kernel 'Shake' passes 'Gen', a global or static variable, to 'std::uniform_real_distribution<>::operator()', which may change it through a non-const reference or pointer; the kernel runs once per particle, in an order that differs between backends and ranks, so the result is not the same everywhere
  // CHECK: note: for random numbers use wash::random(key, stream), the same on every backend; if sharing this state is deliberate, call wash::allow_shared_state() in kernel 'Shake'
  double u = std::uniform_real_distribution<>(0.0, 1.0)(Gen);
  // CHECK: global-engine-in-particle-kernel.cpp:[[@LINE+1]]:36: error: update kernel 'Shake' passes 'Gen', a global or static variable, to 'jitter'
  p.set_mass(p.get_mass() + jitter(Gen) + u);
  std::uniform_int_distribution<int> pick(0, 1);
  // CHECK: global-engine-in-particle-kernel.cpp:[[@LINE+1]]:20: error: update kernel 'Shake' passes 'Engines'
  int which = pick(Engines[1]);
  p.set_density(p.get_density() + which);
}

int main() {
  wash::add_update_kernel(&Shake);
  wash::start();
}
