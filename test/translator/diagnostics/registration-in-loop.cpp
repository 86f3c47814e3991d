// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_mass(1); }
void addOne() { wash::add_update_kernel(&update); }

int main(int argc, char **) {
  for (int i = 0; i < argc; ++i)
    // CHECK: registration-in-loop.cpp:[[@LINE-4]]:17: error: call to 'wash::add_update_kernel' inside a loop; the translator cannot tell how many times it runs
    addOne();
  wash::start();
}
