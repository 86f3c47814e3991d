// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: force-dim-invalid.cpp:[[@LINE+1]]:27: error: force 'spin' has dimension 3; it must be 1 (scalar) or 2 (a vector of this 2-dimensional simulation)
  wash::add_force("spin", 3);
  wash::start();
}
