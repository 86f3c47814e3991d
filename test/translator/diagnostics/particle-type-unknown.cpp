// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

#include <vector>

void update(wash::Particle &p) {
  // CHECK: particle-type-unknown.cpp:[[@LINE+1]]:17: error: particle type 'wal' is never added with wash::add_particle_type
  if (p.is_type("wal"))
    p.set_vel({});
}

void force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  for (const wash::Particle &n : ns)
    p.set_density(n.get_density());
}

int main() {
  wash::add_particle_type("fluid");
  wash::add_particle_type("wall");
  wash::set_influence_radius(1.0);
  wash::add_update_kernel(&update);
  wash::add_force_kernel(&force, "fluid", "wall");
  wash::start();
}
