// RUN: %wash --version | FileCheck %s
// CHECK: wash 0.1.0 (LLVM 19.{{[0-9.]+}})
