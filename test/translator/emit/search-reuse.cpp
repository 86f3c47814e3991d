// One cell sort per neighbour search: force kernels with no write to pos
// between them share it; an update kernel that moves particles forces a new one.
// RUN: rm -rf %t && %wash --backend=openmp -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/search-reuse.openmp.cpp | FileCheck %s
// CHECK-LABEL: // A: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos.
// CHECK-NEXT: search(wash::backend::fixedGeometry(run.radius()), run.box(),
// CHECK-LABEL: // B: force kernel, reuses the neighbour search of 'A'
// CHECK-NOT: search(
// CHECK-LABEL: // Move: update kernel
// CHECK-NOT: search(
// CHECK-LABEL: // C: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos.
// CHECK-NEXT: search(wash::backend::fixedGeometry(run.radius()), run.box(),
#include <wash/wash.hpp>
#include <vector>

void A(wash::Particle& p, const std::vector<wash::Particle>& ns) { p.set_density(ns.size()); }
void B(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  p.set_force_scalar("b", ns.empty() ? 0.0 : ns[0].get_density());
}
void Move(wash::Particle& p) { p.set_pos(p.get_pos() + p.get_vel() * 0.01); }
void C(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  p.set_force_scalar("c", double(ns.size()));
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&A);
  wash::add_force_kernel(&B);
  wash::add_update_kernel(&Move);
  wash::add_force_kernel(&C);
  wash::set_max_iterations(1);
  wash::start();
}
