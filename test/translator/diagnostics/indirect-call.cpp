// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void touch(wash::Particle &p) { p.set_mass(1); }
void (*hook)(wash::Particle &) = &touch;

void update(wash::Particle &p) {
  // CHECK: indirect-call.cpp:[[@LINE+1]]:3: error: call through a function pointer in kernel 'update' hides which particle properties it accesses
  hook(p);
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
