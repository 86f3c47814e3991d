// A registered force nothing touches is dead (with a warning); one written but
// never read is live for output only; acc untouched is dead; mass is always
// output so it stays live though untouched.
// RUN: %wash --dump-model %s 2> %t.err | FileCheck %s
// RUN: FileCheck %s --check-prefix=WARN < %t.err
#include <wash/wash.hpp>

void update(wash::Particle &p) { p.set_force_scalar("written", p.get_force_scalar("read") + 1), p.set_force_scalar("read", 0.0); }

int main() {
  wash::add_force("read", 1);
  wash::add_force("written", 1);
  // WARN: liveness-dead-and-output-only.cpp:[[@LINE+1]]:19: warning: force 'unused' is registered but never read or written; it gets no storage
  wash::add_force("unused", 2);
  wash::add_update_kernel(&update);
  wash::start();
}
// CHECK:      acc: builtin vector2 dead
// CHECK:      mass: builtin scalar live
// CHECK-NOT:  output-only
// CHECK:      read: registered scalar live @11:19
// CHECK-NEXT: written: registered scalar live output-only @12:19
// CHECK-NEXT: unused: registered vector2 dead @14:19
