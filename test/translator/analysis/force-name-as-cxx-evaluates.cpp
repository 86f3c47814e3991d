// Force names are evaluated as C++ evaluates them: a literal reaches the
// std::string parameter as a const char *, so it ends at its first NUL, and
// "heat\0wave" names the force 'heat' (as in the reference runtime); a
// pointer into a literal names what it points to.
// RUN: %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=warning: --implicit-check-not=error:
#include <wash/wash.hpp>

void Heat(wash::Particle &p) {
  p.set_force_scalar("heat\0wave", p.get_force_scalar("heat") + 1.0);
  p.set_force_scalar(&"heatwave"[4], p.get_force_scalar("wave") + 1.0);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("heat", 1);
  wash::add_force("wave", 1);
  wash::add_update_kernel(&Heat);
  wash::start();
}
// CHECK:      {{^}}  heat: registered scalar live @15:19{{$}}
// CHECK-NEXT: {{^}}  wave: registered scalar live @16:19{{$}}
// CHECK-NEXT: kernels
// CHECK:        own-reads: heat wave{{$}}
// CHECK-NEXT:   own-writes: heat wave{{$}}
