// The driver saves and restores every stored column by name (checkpoints,
// docs/semantics.md), restores instead of running the init kernels, and
// checks for a due checkpoint or a stop signal after every step. The
// program's identity names its kernels and columns, never the backend.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/checkpoint-driver.serial.cpp | FileCheck %s
// RUN: %wash --backend=mpi -o %t/mpi %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/mpi/checkpoint-driver.mpi.cpp | FileCheck %s
// CHECK: const auto checkpointColumns = [](auto f) {
// CHECK-NEXT: f("id", P.id);
// CHECK-NEXT: f("pos", P.pos);
// CHECK-NEXT: f("vel", P.vel);
// CHECK-NEXT: f("density", P.density);
// CHECK-NEXT: f("mass", P.mass);
// CHECK-NEXT: f("smoothing_length", P.smoothing_length);
// CHECK-NEXT: f("heat", P.heat);
// CHECK-NEXT: };
// CHECK: .floatStorage = false, .smoothingLengthSearch = false,
// CHECK-NEXT: .program = "kernels: init Spawn; force Count; update Drift; columns: id pos vel density mass smoothing_length heat"};
// CHECK: if (run.restarting()) {
// CHECK-NEXT: particles = wash::backend::restoreCheckpoint(backend, run, P, checkpointColumns, [&] { return run.radius(); });
// CHECK-NEXT: } else {
// CHECK-NEXT: ::Spawn(); // init kernel
// CHECK: run.begin(particles, frame);
// CHECK-NEXT: }
// CHECK-NEXT: for (std::uint64_t step = run.firstStep(); step <= run.steps(); ++step) {
// CHECK: run.endStep(step, frame);
// CHECK-NEXT: wash::backend::afterStep(backend, run, step, particles, checkpointColumns);
// CHECK-NEXT: }
#include <wash/wash.hpp>
#include <vector>

void Spawn() {
  for (int i = 0; i < 4; i++)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{0.0, 0.0});
}
void Count(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  p.set_density(double(ns.size()));
  p.set_force_scalar("heat", p.get_force_scalar("heat") + 1.0);
}
void Drift(wash::Particle& p) { p.set_pos(p.get_pos() + wash::Vec2D{0.01, 0.0}); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("heat", 1);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Count);
  wash::add_update_kernel(&Drift);
  wash::set_max_iterations(3);
  wash::start();
}
