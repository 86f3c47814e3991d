// Flags after `--` reach the compiler; WASH_DIM given there wins over the guess.
// RUN: %wash --dump-model %s -- -DHEAT_NAME=\"heat\" -DWASH_DIM=3 | FileCheck %s
// CHECK: dimension: 3
// CHECK: heat: registered vector3
#include <wash/wash.hpp>
int main() {
  wash::add_force(HEAT_NAME, 3);
  wash::start();
}
