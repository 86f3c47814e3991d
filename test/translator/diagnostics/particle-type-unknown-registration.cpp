// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

#include <vector>

void force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  for (const wash::Particle &n : ns)
    p.set_density(n.get_density());
}

int main() {
  wash::add_particle_type("fluid");
  wash::set_influence_radius(1.0);
  // CHECK: particle-type-unknown-registration.cpp:[[@LINE+1]]:43: error: particle type 'sand' is never added with wash::add_particle_type
  wash::add_force_kernel(&force, "fluid", "sand");
  wash::start();
}
