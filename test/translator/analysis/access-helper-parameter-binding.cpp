// A helper taking `const wash::Particle&` counts as a neighbour access when
// called with a neighbour and as an own access when called with the particle.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

double readDensity(const wash::Particle &p) { return p.get_density(); }
wash::Vec2D readVel(const wash::Particle &p) { return p.get_vel(); }
void writeMass(wash::Particle &p, double m) { p.set_mass(m); }

void kernel(wash::Particle &self, const std::vector<wash::Particle> &neighbours) {
  double sum = 0;
  for (const wash::Particle &n : neighbours)
    sum += readDensity(n);
  writeMass(self, sum + readVel(self).at(0));
}

int main() {
  wash::add_force_kernel(&kernel);
  wash::start();
}
// CHECK:      0: force kernel
// CHECK-NEXT:   own-reads: vel
// CHECK-NEXT:   own-writes: mass
// CHECK-NEXT:   always-writes: mass
// CHECK-NEXT:   neighbour-reads: density
// CHECK-NEXT:   hazards: -
