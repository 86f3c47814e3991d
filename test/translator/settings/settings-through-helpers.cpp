// Settings come from main and the functions it calls, with constants folded.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

constexpr double h = 0.5;
void configure() {
  wash::set_precision("float");
  wash::set_influence_radius(2 * h);
  wash::add_force("heat", 1);
}

int main() {
  configure();
  wash::set_simulation_name("demo");
  wash::set_max_iterations(10 * 3);
  wash::start();
}
// CHECK:      precision: float
// CHECK-NEXT: dimension: 2
// CHECK-NEXT: influence-radius: 1 @8:30
// CHECK-NEXT: smoothing-length-support: unset
// CHECK-NEXT: max-iterations: 30 @15:28
// CHECK-NEXT: simulation-name: "demo" @14:29
// CHECK-NEXT: output-file-name: unset
// CHECK:      heat: registered scalar dead @9:19
