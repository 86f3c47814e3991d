// Without a cast the compiler rejects it first: clang's own error, status 1.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void update(wash::Particle &p, const std::vector<wash::Particle> &) { p.set_mass(1); }

int main() {
  // CHECK: kernel-wrong-signature-uncast.cpp:[[@LINE+1]]:27: error: cannot initialize a parameter of type 'UpdateKernel'
  wash::add_update_kernel(&update);
  wash::start();
}
