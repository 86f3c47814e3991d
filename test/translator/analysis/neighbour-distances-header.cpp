// A distance computed in a helper of the user's own header reads the
// distance the search keeps, as one in the simulation file does: uses are
// keyed by file, line and column, so the header's line 8 is not the main
// file's line 8.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
// RUN: rm -rf %t && %wash --backend=serial -o %t %s
// RUN: FileCheck --check-prefix=HEADER %s < %t/user/Inputs/distances/pair_sum.hpp
// RUN: FileCheck --check-prefix=MAIN %s < %t/neighbour-distances-header.serial.cpp
#include "../Inputs/distances/pair_sum.hpp"

// CHECK-LABEL: neighbour-distances: kept by the search
// CHECK-NEXT: PairSum @8:12: ns.distance(n) for p
// HEADER: ns.distance(n)
// The main file's magnitude is not an offset to a neighbour: it stays.
// MAIN: {{^}}  wash_gen::P.density[p] = PairSum(p, ns) + ({{.*}}).magnitude();
void force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_density(PairSum(p, ns) + (p.get_pos() - p.get_vel()).magnitude());
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(force);
  wash::start();
}
