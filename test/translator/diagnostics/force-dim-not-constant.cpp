// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

int main(int argc, char **) {
  // CHECK: force-dim-not-constant.cpp:[[@LINE+1]]:27: error: dimension of force 'spin' must be a constant
  wash::add_force("spin", argc);
  wash::start();
}
