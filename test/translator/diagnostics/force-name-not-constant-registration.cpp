// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main(int argc, char **argv) {
  // CHECK: force-name-not-constant-registration.cpp:[[@LINE+1]]:19: error: force name must be a string literal
  wash::add_force(argv[0], 1);
  wash::start();
}
