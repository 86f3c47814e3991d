// Under the symmetric smoothing-length rule every force kernel's search reads
// h on its particle and on its neighbours (so halos carry it); the gather
// rule, the default or named, reads only the particle's.
// RUN: %wash --dump-model %s | FileCheck %s
// RUN: %wash --dump-model %s -- -DGATHER | FileCheck %s --check-prefix=GATHER
#include <wash/wash.hpp>

void density(wash::Particle &p, const std::vector<wash::Particle> &ns) { p.set_density(ns.size()); }

int main() {
#ifdef GATHER
  wash::set_smoothing_length_support(2.0, wash::Support::Gather);
#else
  wash::set_smoothing_length_support(2.0, wash::Support::Symmetric);
#endif
  wash::add_force_kernel(&density);
  wash::start();
}
// CHECK:      smoothing-length-support: 2 @
// CHECK-NEXT: support-rule: symmetric (pairs within k max(h_i, h_j))
// CHECK-LABEL: kernels
// CHECK:      0: force density
// CHECK-NEXT:   own-reads: smoothing_length
// CHECK:        neighbour-reads: smoothing_length
// CHECK:        halo: pos smoothing_length
// GATHER:      smoothing-length-support: 2 @
// GATHER-NOT:  support-rule
// GATHER-LABEL: kernels
// GATHER:       0: force density
// GATHER-NOT:   neighbour-reads: {{.*}}smoothing_length
// GATHER-LABEL: neighbour-searches
