// --profile: every kernel of a step, whatever its kind, marks where its time
// begins (run.kernel, one branch when off), before its search or snapshot.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/profile-marks.serial.cpp | FileCheck %s
// CHECK: ::Spawn(); // init kernel
// CHECK-NOT: run.kernel(
// CHECK: for (std::uint64_t step = run.firstStep(); step <= run.steps(); ++step) {
// CHECK-NEXT: run.kernel("Density"); // its time begins (--profile)
// CHECK-NEXT: // Density: force kernel, new neighbour search
// CHECK: run.kernel("Move"); // its time begins (--profile)
// CHECK-NEXT: // Move: update kernel
// CHECK: run.kernel("Largest"); // its time begins (--profile)
// CHECK-NEXT: // Largest: reduction kernel
// CHECK: run.kernel("Report"); // its time begins (--profile)
// CHECK-NEXT: // Report: void kernel
// CHECK-NOT: run.kernel(
// CHECK: run.endStep(step, frame);
#include <wash/wash.hpp>
#include <vector>

void Spawn() {
  for (int i = 0; i < 4; i++)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{0.0, 0.0});
}
void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_density(ns.size()); }
void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel() * 0.01); }
double Largest(const wash::Particle &p) { return p.get_density(); }
void Report() {}

int main() {
  wash::set_influence_radius(0.2);
  wash::add_variable("largest", 0.0);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Density);
  wash::add_update_kernel(&Move);
  wash::add_reduction_kernel(&Largest, wash::Reduction::Max, "largest");
  wash::add_void_kernel(&Report);
  wash::set_max_iterations(1);
  wash::start();
}
