// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void elsewhere(wash::Particle &p);

int main() {
  // CHECK: kernel-not-defined.cpp:[[@LINE+1]]:27: error: kernel 'elsewhere' is not defined in this translation unit
  wash::add_update_kernel(&elsewhere);
  wash::start();
}
// CHECK: kernel-not-defined.cpp:4:6: note: 'elsewhere' declared here
