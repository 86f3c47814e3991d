// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

#include <vector>

void mark(wash::Particle &n) { n.set_type("wall"); }

void update(wash::Particle &p) { mark(p); }

void force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  for (const wash::Particle &n : ns) {
    wash::Particle copy = n;
    // CHECK: set-type-on-neighbour.cpp:[[@LINE+1]]:10: error: 'set_type' on a neighbour particle; a kernel sets only its own particle's type
    copy.set_type("wall");
  }
  p.set_density(1.0);
}

int main() {
  wash::add_particle_type("fluid");
  wash::add_particle_type("wall");
  wash::set_influence_radius(1.0);
  wash::add_update_kernel(&update);
  wash::add_force_kernel(&force);
  wash::start();
}
