// The dimension comes from the vector type the code spells; no -DWASH_DIM.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

void init() { wash::create_particle(1, 1, 1, wash::Vec3D{0.0, 0.0, 0.0}, wash::Vec3D{}); }

int main() {
  wash::add_force("spin", 3);
  wash::add_init_kernel(&init);
  wash::start();
}
// CHECK: dimension: 3
// CHECK: pos: builtin vector3 live
// CHECK: spin: registered vector3 dead
