// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main() {
  // CHECK: precision-invalid.cpp:[[@LINE+1]]:23: error: precision must be the constant "double" or "float"
  wash::set_precision("half");
  wash::start();
}
