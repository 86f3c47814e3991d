// A header without a guard, included twice, is one file of the generated
// project and each of its accesses is rewritten once (it used to be rewritten
// once per inclusion, nested into itself: P.mass[P.mass[p] = ...]).
// RUN: rm -rf %t
// RUN: %wash --backend=serial -o %t %s
// RUN: FileCheck %s < %t/user/Inputs/twice/double_mass.hpp
// RUN: %cxx_check -I%t %t/header-included-twice.serial.cpp
#include <wash/wash.hpp>

namespace first {
#include "../Inputs/twice/double_mass.hpp"
}
#include "../Inputs/twice/double_mass.hpp"

void Step(wash::Particle &p) { DoubleMass(p); }

int main() {
  wash::set_influence_radius(0.5);
  wash::add_update_kernel(&Step);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK:      inline void DoubleMass(wash_gen::Self &p) {
// CHECK-NEXT:   wash_gen::P.mass[p] = wash_gen::P.mass[p] * 2.0;
// CHECK-NEXT: }
