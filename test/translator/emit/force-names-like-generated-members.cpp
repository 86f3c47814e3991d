// Force names that are valid but equal a name of the generated storage (its
// members size and forEachColumn, the force_<n>_ prefix of mangled members, a
// reserved _Upper name) get mangled members: the generated code compiles.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>&1 | count 0
// RUN: %cxx_check -I%t %t/force-names-like-generated-members.serial.cpp
// RUN: FileCheck %s < %t/force-names-like-generated-members.wash.hpp
#include <wash/wash.hpp>

void Heat(wash::Particle &p) {
  p.set_force_scalar("size", p.get_force_scalar("size") + 1.0);
  p.set_force_scalar("forEachColumn", p.get_force_scalar("forEachColumn") + 1.0);
  p.set_force_scalar("force_9_x", p.get_force_scalar("force_9_x") + 1.0);
  p.set_force_scalar("_Heat", p.get_force_scalar("_Heat") + 1.0);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("size", 1);
  wash::add_force("forEachColumn", 1);
  wash::add_force("force_9_x", 1);
  wash::add_force("_Heat", 1);
  wash::add_update_kernel(&Heat);
  wash::start();
}
// CHECK: Column<Real> force_8_size;
// CHECK: Column<Real> force_9_forEachColumn;
// CHECK: Column<Real> force_10_force_9_x;
// CHECK: Column<Real> force_11__Heat;
