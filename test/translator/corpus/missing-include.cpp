// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// CHECK: fatal error: 'no/such/header.hpp' file not found
#include <no/such/header.hpp>
int main() {}
