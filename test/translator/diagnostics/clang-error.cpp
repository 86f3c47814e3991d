// A source clang rejects gets clang's errors only, and status 1.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: clang-error.cpp:[[@LINE+1]]:9: error: no member named 'add_forces' in namespace 'wash'
  wash::add_forces("x", 1);
}
// CHECK-NOT: never calls
