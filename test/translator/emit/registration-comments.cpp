// Each registration is replaced by a comment saying what it registered: the
// call as written, whitespace collapsed, with no `*/` or `/*` left to end or
// nest the comment (the program compiles without -Wcomment warnings). A call
// over several lines keeps its newlines, so the user's line numbers still hold
// after it. Settings stay calls.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: %cxx_check -Wcomment -Werror -I%t %t/registration-comments.serial.cpp
// RUN: grep -vE '^// [A-Z-]+:' %t/registration-comments.serial.cpp | FileCheck %s
// RUN: awk '/^#line 1 /{o=NR} /^ *wash_gen::start[(][)];/{print NR-o}' %t/registration-comments.serial.cpp | FileCheck --check-prefix=LINE %s
#include <wash/wash.hpp>
#include <vector>

void Push(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  p.set_force_scalar("heat", p.get_force_scalar("heat") + double(ns.size()));
}

double Heat(const wash::Particle& p) { return p.get_force_scalar("heat"); }

// CHECK: int main() {
// CHECK-NEXT: wash::set_influence_radius(0.1);
// CHECK-NEXT: (void)0 /* wash::add_force("heat", 1): registered by the translator */;
// CHECK-NEXT: wash::add_variable("total", 0.0);
// CHECK-NEXT: (void)0 /* wash::add_force_kernel(
// CHECK-NEXT: &Push / * the kernel * / // and a line comment
// CHECK-NEXT: ): run by the driver */;
// CHECK-NEXT: (void)0 /* wash::add_reduction_kernel(&Heat, wash::Reduction::Sum, "total"): run by the driver */;
// CHECK-NEXT: wash::set_max_iterations(1);
// CHECK: wash_gen::start();
int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("heat",   1);
  wash::add_variable("total", 0.0);
  wash::add_force_kernel(  
      &Push   /* the kernel */ // and a line comment
  );
  wash::add_reduction_kernel(&Heat,	wash::Reduction::Sum, "total");
  wash::set_max_iterations(1);
  // LINE: [[#@LINE+1]]
  wash::start();
}
