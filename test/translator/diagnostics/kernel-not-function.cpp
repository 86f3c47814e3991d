// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_mass(1); }

int main(int argc, char **) {
  wash::UpdateKernel k = argc > 1 ? &update : nullptr;
  // CHECK: kernel-not-function.cpp:[[@LINE+1]]:27: error: kernel must name a function
  wash::add_update_kernel(k);
  // CHECK: kernel-not-function.cpp:[[@LINE+1]]:27: error: kernel must name a function
  wash::add_update_kernel([](wash::Particle &p) { p.set_mass(2); });
  wash::start();
}
