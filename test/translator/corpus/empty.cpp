// RUN: %expect_exit 1 %wash --dump-model %S/../Inputs/empty.txt 2>&1 | FileCheck %s
// CHECK: error: no 'main' function
