// A tank: mass is written only by the init kernel. The halo rows kept from
// the previous search never receive it again; only rows new to the halo do.
// The same holds for the dam break example.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
// RUN: %wash --dump-model %wash_src/examples/dam_break_2d/dam_break_2d.cpp 2>/dev/null \
// RUN:   | FileCheck %s --check-prefix=DAM
#include <wash/wash.hpp>
#include <vector>

void Spawn() {
  for (int i = 0; i < 10; ++i)
    wash::create_particle(1000.0, 0.1, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{});
}

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel() * 0.01); }

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = 0;
  for (const auto &n : ns)
    d += n.get_mass();
  p.set_density(d);
}
// CHECK-LABEL: force Density
// CHECK:      halo: pos mass
// CHECK-NEXT: halo-exchange (new rows): pos mass{{$}}
// CHECK-NEXT: halo-exchange (rows kept from the previous search): pos{{$}}
// CHECK-NEXT: halo-not-sent: mass (kept rows: not written since they were last sent)

void Forces(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec2D a{};
  for (const auto &n : ns)
    a += (p.get_pos() - n.get_pos()) * (n.get_mass() * n.get_density());
  p.set_vel(p.get_vel() + a);
}
// CHECK-LABEL: force Forces
// CHECK:      halo: pos density mass
// CHECK-NEXT: halo-exchange: density{{$}}
// CHECK-NEXT: halo-not-sent: pos mass (not written since they were last sent)

// DAM-LABEL: force Walls
// DAM:      halo-exchange (new rows): pos vel density mass type pressure{{$}}
// DAM-NEXT: halo-exchange (rows kept from the previous search): pos vel density pressure{{$}}
// DAM-NEXT: halo-not-sent: type (kept rows: not written since they were last sent)
// DAM-LABEL: force Rates
// DAM:      halo-exchange: density pressure wall_vel{{$}}
// DAM-NEXT: halo-not-sent: pos vel mass type (not written since they were last sent)

int main() {
  wash::set_influence_radius(0.25);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Move);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Forces);
  wash::set_max_iterations(3);
  wash::start();
}
