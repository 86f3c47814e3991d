// A warning only: the model is still printed and the status is 0.
// RUN: %expect_exit 0 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

// CHECK: missing-start.cpp:[[@LINE+1]]:5: warning: 'main' never calls 'wash::start'; the simulation does not run
int main() { wash::set_max_iterations(1); }
// CHECK: starts: no
