// A name reaching the API through a helper's parameter is the caller's
// argument, as in C++, and the default only where the caller passes none:
// Bump(p, "beta") writes beta, not the default alpha. Registration helpers
// bind their parameters call by call (main's walk follows each call), so
// one helper may register several names.
// RUN: %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: rm -rf %t && %wash --backend=serial -o %t %s
// RUN: FileCheck --check-prefix=CODE %s < %t/names-bound-by-the-caller.serial.cpp
#include <wash/wash.hpp>
#include <string>

void Bump(wash::Particle &p, const char *const name = "alpha") {
  p.set_force_scalar(name, p.get_force_scalar(name) + 1.0);
}
void Decay(wash::Particle &p, const std::string &name = "gamma") {
  p.set_force_scalar(name, p.get_force_scalar(name) * 0.5);
}
void Step(wash::Particle &p) {
  Bump(p, "beta");
  Decay(p);
}

void addScalar(const std::string &name, int dim = 1) { wash::add_force(name, dim); }
void addType(const char *name) { wash::add_particle_type(name); }

int main() {
  wash::set_influence_radius(0.5);
  addScalar("alpha");
  addScalar("beta");
  addScalar("gamma", 1);
  addType("fluid");
  addType("wall");
  wash::add_update_kernel(&Step, "fluid");
  wash::start();
}
// CHECK: warning: force 'alpha' is registered but never read or written
// CHECK:      alpha: registered scalar dead
// CHECK:      beta: registered scalar live
// CHECK:      gamma: registered scalar live
// CHECK:        own-reads: {{.*}}beta gamma
// CHECK-NEXT:   own-writes: beta gamma{{$}}
// CODE:      P.beta[p] = {{.*}}P.beta[p] + 1.0
// CODE:      P.gamma[p] = {{.*}}P.gamma[p] * 0.5
