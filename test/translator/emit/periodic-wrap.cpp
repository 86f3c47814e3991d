// Positions wrap into a periodic box after the kernels that write pos, and
// only after those; the neighbour search (the backend's) adds periodic images.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/periodic-wrap.serial.cpp | FileCheck %s
// CHECK: backend.search(P, at, box, wash::backend::HaloColumns<Kept, Fresh>{kept, fresh});
// CHECK-LABEL: // Count: force kernel, new neighbour search
// CHECK-NOT: wrapPositions
// CHECK-LABEL: // Drift: update kernel
// CHECK: ::Drift(self);
// CHECK-NEXT: return wash::backend::finite(P.pos[i]);
// CHECK-NEXT: });
// CHECK-NEXT: wash::backend::wrapPositions(P.pos, backend.owned(), run.box());
// CHECK-NEXT: if (!wroteFinite1) {
// CHECK-NEXT: run.checkFinite(P.pos, P.id, backend.owned(), step, "Drift", "pos");
#include <wash/wash.hpp>
#include <vector>

void Count(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_density(double(ns.size()));
}
void Drift(wash::Particle &p) { p.set_pos(p.get_pos() + wash::Vec2D{0.01, 0.0}); }

int main() {
  wash::set_influence_radius(0.1);
  wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, false});
  wash::add_force_kernel(&Count);
  wash::add_update_kernel(&Drift);
  wash::set_max_iterations(1);
  wash::start();
}
