// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: force-registered-twice.cpp:[[@LINE+3]]:19: error: force 'heat' is registered more than once
  // CHECK: force-registered-twice.cpp:[[@LINE+1]]:19: note: 'heat' registered here
  wash::add_force("heat", 1);
  wash::add_force("heat", 1);
  wash::start();
}
