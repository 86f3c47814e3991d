// A variable may have any name; the reduction that sets it names it in the
// generated driver as an escaped string literal, so the code compiles.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>&1 | count 0
// RUN: %cxx_check -I%t %t/reduction-variable-escaped.serial.cpp
// RUN: FileCheck %s < %t/reduction-variable-escaped.serial.cpp
#include <wash/wash.hpp>

double Height(const wash::Particle &p) { return p.get_pos().at(1); }

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }

int main() {
  wash::set_influence_radius(0.5);
  wash::add_variable("top \"h\"\\\t", 0.0);
  wash::add_update_kernel(&Move);
  wash::add_reduction_kernel(&Height, wash::Reduction::Max, "top \"h\"\\\t");
  wash::start();
}
// CHECK: {{^ +}}wash::set_variable("top \"h\"\\\011", backend.reduce(
