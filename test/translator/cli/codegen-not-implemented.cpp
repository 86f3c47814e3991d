// The MPI backend is not generated yet: asking for it fails honestly, in one
// line, and writes nothing.
// RUN: rm -rf %t.dir
// RUN: %expect_exit 1 %wash --backend=mpi -o %t.dir %s 2>&1 | FileCheck %s
// RUN: test ! -e %t.dir
// CHECK: wash: error: code generation for the 'mpi' backend is not implemented yet
// CHECK-EMPTY:
#include <wash/wash.hpp>
int main() { wash::start(); }
