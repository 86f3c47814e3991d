// C library generators keep their state hidden in the library: drawn per
// particle, the numbers depend on the order particles run in.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <cstdlib>
#include <random>
#include <stdlib.h>

double noise() {
  // CHECK-DAG: shared-state-call-in-particle-kernel.cpp:[[@LINE+2]]:10: error: update kernel 'Stir' calls 'rand', which changes state hidden in the library; the kernel runs once per particle, in an order that differs between backends and ranks, so the result is not the same everywhere
  // CHECK-DAG: note: for random numbers use wash::random(key, stream), the same on every backend; if sharing this state is deliberate, call wash::allow_shared_state() in kernel 'Stir'
  return std::rand() / double(RAND_MAX);
}

void Stir(wash::Particle &p) {
  // CHECK-DAG: shared-state-call-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Stir' calls 'srand'
  std::srand(7);
  // CHECK-DAG: shared-state-call-in-particle-kernel.cpp:[[@LINE+1]]:24: error: update kernel 'Stir' calls 'random'
  double r = noise() + random();
  // CHECK-DAG: shared-state-call-in-particle-kernel.cpp:[[@LINE+1]]:8: error: update kernel 'Stir' calls 'drand48'
  r += drand48();
  std::random_device device;
  // CHECK-DAG: shared-state-call-in-particle-kernel.cpp:[[@LINE+1]]:8: error: update kernel 'Stir' calls 'std::random_device::operator()'
  r += device();
  p.set_mass(p.get_mass() + r);
}

int main() {
  wash::add_update_kernel(&Stir);
  wash::start();
}
