// A kernel of the wrong type only gets past the compiler through a cast.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p, double dt) { p.set_mass(dt); }

int main() {
  // CHECK: kernel-wrong-signature.cpp:[[@LINE+1]]:27: error: update kernel 'update' has type 'void (wash::Particle &, double)' but must have type 'void (wash::Particle &)'
  wash::add_update_kernel(reinterpret_cast<wash::UpdateKernel>(&update));
  wash::start();
}
// CHECK: kernel-wrong-signature.cpp:5:6: note: 'update' declared here
