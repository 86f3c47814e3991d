// Under the smoothing-length rule every force kernel's search reads h on its
// particle, and a write to h (like one to pos) starts a new search.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

void density(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_density(ns.size()); }
void adapt(wash::Particle &p) { p.set_smoothing_length(p.get_smoothing_length() * 1.1); }
void pressure(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_acc(p.get_pos()); }
void count(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_mass(ns.size()); }

int main() {
  wash::set_smoothing_length_support(2.0);
  wash::add_force_kernel(&density);
  wash::add_update_kernel(&adapt);
  wash::add_force_kernel(&pressure);
  wash::add_force_kernel(&count);
  wash::start();
}
// CHECK:      smoothing-length-support: 2 @12:38
// CHECK:      smoothing_length: builtin scalar live{{$}}
// CHECK-LABEL: kernels
// CHECK:      0: force density
// CHECK-NEXT:   own-reads: smoothing_length
// CHECK:      2: force pressure
// CHECK-NEXT:   own-reads: pos smoothing_length
// CHECK-LABEL: neighbour-searches
// CHECK-NEXT:   0: density
// CHECK-NEXT:   1: pressure count
