// An alias of the particle type names the generated particle type (it used to
// become `using Particle = auto;`); its uses are rewritten where they are.
// RUN: rm -rf %t
// RUN: %wash --backend=serial -o %t %s
// RUN: FileCheck %s < %t/particle-type-alias.serial.cpp
// RUN: %cxx_check -I%t %t/particle-type-alias.serial.cpp
#include <wash/wash.hpp>
#include <vector>

using Particle = wash::Particle;
typedef wash::Particle Body;
using Neighbours = std::vector<wash::Particle>;

void Spread(Particle &p, const Neighbours &ns) {
  double sum = 0.0;
  for (const Body &q : ns)
    sum += q.get_mass();
  p.set_density(sum);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force_kernel(&Spread);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK:      using Particle = wash_gen::Self;
// CHECK-NEXT: typedef wash_gen::Self Body;
// CHECK-NEXT: using Neighbours = wash_gen::NeighbourList;
// CHECK:      void Spread(wash_gen::Self &p, const wash_gen::NeighbourList &ns) {
// CHECK:        for (const auto &q : ns)
