// A reduction kernel reads its own particle only, and says what it computes.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
#include <wash/wash.hpp>

double Speed(const wash::Particle &p) { return p.get_vel().magnitude() / p.get_smoothing_length(); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_variable("fastest", 0.0);
  wash::add_reduction_kernel(&Speed, wash::Reduction::Max, "fastest");
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK: 0: reduction Speed
// CHECK-NEXT: own-reads: vel smoothing_length
// CHECK-NEXT: own-writes: -
// CHECK-NEXT: reduce: max into 'fastest'
