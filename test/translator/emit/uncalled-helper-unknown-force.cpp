// A helper no kernel calls may name forces nothing else uses: they have no
// field, so its reads become zeros and its writes keep only the value's side
// effects. The program translates with no diagnostic and compiles (this used
// to abort with std::out_of_range from map::at).
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>&1 | count 0
// RUN: %cxx_check -I%t %t/uncalled-helper-unknown-force.serial.cpp
// RUN: grep -vE "^// [A-Z-]+:" %t/uncalled-helper-unknown-force.serial.cpp | FileCheck %s
#include <wash/wash.hpp>

// CHECK: {{^}}void Unused(wash_gen::Self &q) { (void)(double()); }
void Unused(wash::Particle &q) { q.set_force_scalar("ghost", q.get_force_scalar("ghost2")); }
// CHECK: {{^}}wash::ParticleVec Drift(wash_gen::Self &q) { return wash::ParticleVec(); }
wash::ParticleVec Drift(wash::Particle &q) { return q.get_force_vector("ghost3"); }

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }

void Init() { wash::create_particle(1.0, 1.0, 0.1, {0.0, 0.0}, {0.1, 0.0}); }

int main() {
  wash::set_influence_radius(0.5);
  wash::add_init_kernel(&Init);
  wash::add_update_kernel(&Move);
  wash::start();
}
