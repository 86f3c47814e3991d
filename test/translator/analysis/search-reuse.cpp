// Force kernels share a neighbour search unless pos is written in between,
// by an update kernel or by the earlier force kernel itself.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

void a(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_density(ns.size()); }
void b(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_mass(ns.size()); }
void moves(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_pos(p.get_pos()); }
void c(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_mass(1); }
void step(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }
void still(wash::Particle &p) { p.set_vel(p.get_vel()); }

int main() {
  wash::add_force_kernel(&a);
  wash::add_update_kernel(&still);
  wash::add_force_kernel(&b);
  wash::add_force_kernel(&moves);
  wash::add_force_kernel(&c);
  wash::add_update_kernel(&step);
  wash::add_force_kernel(&a);
  wash::start();
}
// CHECK-LABEL: neighbour-searches
// CHECK-NEXT:   0: a b moves
// CHECK-NEXT:   1: c
// CHECK-NEXT:   2: a
