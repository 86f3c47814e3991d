// RUN: %wash --help | FileCheck %s
// CHECK: wash [options] <simulation.cpp> [-- <compiler flags>]
// CHECK: --backend=<value>
// CHECK: --dump-after=<pass>
// CHECK: --dump-model
// CHECK: -o <dir>
