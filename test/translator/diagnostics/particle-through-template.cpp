// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// Template helpers and generic lambdas taking particles: the accesses in
// them cannot be rewritten, and the generated code did not compile.
#include <wash/wash.hpp>
#include <algorithm>

// CHECK-DAG: particle-through-template.cpp:[[@LINE+1]]:34: note: 'p' declared here
template <class P> void setIt(P &p) { p.set_mass(2); }
// Templates not taking a particle through a template type are fine.
template <class T> T twice(T x) { return 2 * x; }

void Update(wash::Particle &p) {
  // CHECK-DAG: particle-through-template.cpp:[[@LINE+1]]:3: error: 'setIt' receives a particle through a parameter of template type ('auto' or a template parameter); declare the parameter as 'wash::Particle'
  setIt(p);
  // CHECK-DAG: particle-through-template.cpp:[[@LINE+1]]:21: note: 'q' declared here
  auto f = [](auto &q) { q.set_density(1); };
  // CHECK-DAG: particle-through-template.cpp:[[@LINE+1]]:3: error: lambda receives a particle through a parameter of template type
  f(p);
  p.set_smoothing_length(twice(p.get_mass()));
}

void Force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  // CHECK-DAG: particle-through-template.cpp:[[@LINE+2]]:3: error: lambda receives a particle through a parameter of template type
  // CHECK-DAG: particle-through-template.cpp:[[@LINE+1]]:55: note: 'n' declared here
  std::for_each(ns.begin(), ns.end(), [&](const auto &n) { sum += n.get_mass(); });
  p.set_force_scalar("s", sum);
}

int main() {
  wash::add_force("s", 1);
  wash::add_update_kernel(&Update);
  wash::add_force_kernel(&Force);
  wash::start();
}
// CHECK-NOT: lambda using a particle is stored
