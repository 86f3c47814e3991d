// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void Fast(wash::Particle &p) { p.set_mass(1); }

void run(int times) {
  for (int i = 0; i < times; ++i)
    // CHECK: start-repeated.cpp:[[@LINE+1]]:5: error: 'wash::start' may run more than once (inside a loop); the simulation must start exactly once
    wash::start();
}

int main(int argc, char **) {
  wash::add_update_kernel(&Fast);
  if (argc > 1)
    run(argc);
  else
    // CHECK: start-repeated.cpp:[[@LINE+1]]:5: error: 'wash::start' may run more than once (it is reached again here); the simulation must start exactly once
    wash::start();
}
