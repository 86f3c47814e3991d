// A force kernel for one particle type whose neighbours are filtered to
// another writes no particle it reads (force kernels cannot change a type):
// its own writes read through neighbours need no snapshot. Where the types
// overlap (a neighbour of any type, or the kernel's own type) they keep one,
// and the dump says why.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/hazard-disjoint-types.wash.hpp
// RUN: not grep 'density_snap[s]hot' %t/hazard-disjoint-types.wash.hpp %t/hazard-disjoint-types.serial.cpp
#include <wash/wash.hpp>
#include <vector>

// CHECK-LABEL: force WallDensity
// CHECK:      neighbour-reads: density type
// CHECK-NEXT: hazards: -{{$}}
// CHECK-NEXT: no-snapshot: density (writes own wall, reads neighbour fluid: disjoint types)
void WallDensity(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = 0;
  for (const auto &n : ns)
    d += n.get_density();
  p.set_density(d);
}

// CHECK-LABEL: force FluidVel
// CHECK:      hazards: vel (writes own fluid, reads neighbour any type)
// CHECK-NOT:  no-snapshot
void FluidVel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec2D v = p.get_vel();
  for (const auto &n : ns)
    v += n.get_vel() * 0.1;
  p.set_vel(v);
}

// CHECK-LABEL: force FluidPressure
// CHECK:      hazards: pressure (writes own fluid, reads neighbour fluid)
// CHECK-NOT:  no-snapshot
void FluidPressure(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = 0;
  for (const auto &n : ns)
    s += n.get_force_scalar("pressure");
  p.set_force_scalar("pressure", s);
}

// The snapshots left: vel and pressure, not density.
// HEADER-DAG: pressure_snapshot;
// HEADER-DAG: vel_snapshot;

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("pressure", 1);
  wash::add_particle_type("fluid");
  wash::add_particle_type("wall");
  wash::add_force_kernel(&WallDensity, "wall", "fluid");
  wash::add_force_kernel(&FluidVel, "fluid");
  wash::add_force_kernel(&FluidPressure, "fluid", "fluid");
  wash::set_max_iterations(1);
  wash::start();
}
