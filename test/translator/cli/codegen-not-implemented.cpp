// Code generation is the next stage: asking for it fails honestly, in one line.
// RUN: %expect_exit 1 %wash --backend=openmp -o %t.dir %s 2>&1 | FileCheck %s
// CHECK: wash: error: code generation for the 'openmp' backend is not implemented yet; use --dump-model
// CHECK-EMPTY:
#include <wash/wash.hpp>
int main() { wash::start(); }
