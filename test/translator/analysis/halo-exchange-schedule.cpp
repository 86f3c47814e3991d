// The MPI halo plan: a field only read on the particle itself never travels;
// a field read through neighbours is sent once, before the first kernel that
// needs it after it changed; a new neighbour search rebuilds the halo, whose
// rows kept from the previous search receive what changed (and pos), and
// whose new rows receive every field current on the kept ones that is read
// before it is written again.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
#include <wash/wash.hpp>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = p.get_mass();
  for (const auto &n : ns)
    d += n.get_mass();
  p.set_density(d);
}
// CHECK-LABEL: force Density
// CHECK:      halo: pos mass
// CHECK-NEXT: halo-exchange (new rows): pos mass{{$}}
// CHECK-NEXT: halo-exchange (rows kept from the previous search): pos{{$}}
// CHECK-NEXT: halo-not-sent: mass (kept rows: not written since they were last sent)

void Pressure(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = p.get_force_scalar("heat");
  for (const auto &n : ns)
    s += n.get_density() + n.get_mass();
  p.set_force_scalar("pressure", s);
}
// Density changed since the halo was built; mass did not; heat is own-only.
// CHECK-LABEL: force Pressure
// CHECK:      halo: pos density mass
// CHECK-NEXT: halo-exchange: density{{$}}
// CHECK-NEXT: halo-not-sent: pos mass (not written since they were last sent)

void Smooth(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = 0;
  for (const auto &n : ns)
    s += n.get_density() + n.get_force_scalar("pressure");
  p.set_force_scalar("heat", s);
}
// CHECK-LABEL: force Smooth
// CHECK:      halo: pos density pressure
// CHECK-NEXT: halo-exchange: pressure

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }

void Again(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = 0;
  for (const auto &n : ns)
    s += n.get_density();
  p.set_force_scalar("heat", s);
}
// CHECK-LABEL: force Again
// Density was sent before Pressure and not written since; mass is still
// current on the kept rows, and read by Density before anything writes it.
// CHECK:      halo: pos density
// CHECK-NEXT: halo-exchange (new rows): pos density mass{{$}}
// CHECK-NEXT: halo-exchange (rows kept from the previous search): pos{{$}}
// CHECK-NEXT: halo-not-sent: density (kept rows: not written since they were last sent)

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("heat", 1);
  wash::add_force("pressure", 1);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Pressure);
  wash::add_force_kernel(&Smooth);
  wash::add_update_kernel(&Move);
  wash::add_force_kernel(&Again);
  wash::set_max_iterations(1);
  wash::start();
}
