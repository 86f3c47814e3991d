// An error from the compiler driver (an unknown flag after `--`) fails the
// run like any other error: non-zero exit, no model on stdout.
// RUN: %expect_exit 1 %wash --dump-model %s -- -fno-such-flag 2>&1 | FileCheck %s
// CHECK: error: unknown argument: '-fno-such-flag'
// CHECK-NOT: dimension:
#include <wash/wash.hpp>
int main() {
  wash::set_influence_radius(0.1);
  wash::start();
}
