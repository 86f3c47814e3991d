// The force after the first 1000 is refused, at its registration; 1000 are
// accepted. Generated code with more forces takes g++ minutes and gigabytes
// (docs/diagnostics.md, ForceLimit).
// RUN: python3 %S/../Inputs/many_forces.py 1001 > %t-1001.cpp
// RUN: %expect_exit 1 %wash --dump-model %t-1001.cpp 2>&1 | FileCheck %s
// CHECK: force-limit.cpp.tmp-1001.cpp:1004:19: error: force 'f1000' is one force too many: a simulation may use at most 1000 forces, beyond which its generated code takes too long and too much memory to compile
// RUN: python3 %S/../Inputs/many_forces.py 1000 > %t-1000.cpp
// RUN: %wash --dump-model %t-1000.cpp 2>&1 | FileCheck --check-prefix=OK %s
// OK-NOT: error:
// OK: f999: registered scalar
