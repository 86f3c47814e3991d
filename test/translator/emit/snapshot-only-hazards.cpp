// A snapshot copy is made only of a field a force kernel writes on its
// particle and reads through neighbours, and only before that kernel; other
// kernels' neighbours read the live column.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/snapshot-only-hazards.serial.cpp | FileCheck %s
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/snapshot-only-hazards.wash.hpp
// HEADER: inline wash::backend::Column<Stored> vel_snapshot;
// HEADER-NOT: _snapshot;
// CHECK-LABEL: // Smooth: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos and vel.
// CHECK-NEXT: search(wash::backend::fixedGeometry(run.radius()), run.box(),
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); },
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); send(P.density); send(P.vel); });
// CHECK-NEXT: vel_snapshot = P.vel; // written here, read through neighbours
// CHECK-NEXT: vel_neighbour = vel_snapshot.data();
// CHECK-LABEL: // Measure: force kernel, reuses the neighbour search of 'Smooth'
// CHECK-NOT: _snapshot
// CHECK: vel_neighbour = P.vel.data();
// CHECK-NOT: _snapshot
// CHECK: run.endStep
#include <wash/wash.hpp>
#include <vector>

void Smooth(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  wash::Vec2D v = p.get_vel();
  for (const auto& n : ns)
    v += n.get_vel() * 0.1;
  p.set_vel(v);
}

void Measure(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  double d = 0;
  for (const auto& n : ns)
    d += n.get_vel().magnitude() + n.get_density();
  p.set_force_scalar("spread", d);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&Smooth);
  wash::add_force_kernel(&Measure);
  wash::set_max_iterations(1);
  wash::start();
}
