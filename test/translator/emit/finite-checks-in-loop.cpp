// What a kernel writes is tested for finiteness inside its particle loop, right
// after each call; the columns are scanned (to name the first culprit) only if
// a test failed. A kernel that writes no stored field gets the plain loop.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/finite-checks-in-loop.serial.cpp | FileCheck %s
// CHECK-LABEL: // Density: force kernel, new neighbour search
// CHECK: const bool wroteFinite0 = backend.forEachParticleChecked([](Index i) {
// CHECK-NEXT: Self self{i};
// CHECK-NEXT: ::Density(self, NeighbourList(backend.grid(), P.pos, i));
// CHECK-NEXT: return wash::backend::finite(P.density[i]) &
// CHECK-NEXT: wash::backend::finite(P.flux[i]);
// CHECK-NEXT: });
// CHECK-NEXT: if (!wroteFinite0) {
// CHECK-NEXT: run.checkFinite(P.density, P.id, backend.owned(), step, "Density", "density");
// CHECK-NEXT: run.checkFinite(P.flux, P.id, backend.owned(), step, "Density", "flux");
// CHECK-NEXT: }
// CHECK-LABEL: // Look: update kernel
// CHECK-NEXT: backend.forEachParticle([](Index i) {
// CHECK-NEXT: Self self{i};
// CHECK-NEXT: ::Look(self);
// CHECK-NEXT: });
// CHECK-NOT: checkFinite
// CHECK: run.endStep(step, frame);
#include <wash/wash.hpp>
#include <iostream>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = p.get_mass();
  for (const auto &n : ns)
    d += n.get_mass();
  p.set_density(d);
  p.set_force_vector("flux", p.get_vel() * d);
}

void Look(wash::Particle &p) {
  if (p.get_density() < 0.0)
    std::cout << "negative density\n";
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("flux", 2);
  wash::add_force_kernel(&Density);
  wash::add_update_kernel(&Look);
  wash::set_max_iterations(1);
  wash::start();
}
