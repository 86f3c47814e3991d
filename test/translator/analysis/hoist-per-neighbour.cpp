// In a neighbour loop, the largest expressions that depend only on the
// neighbour's fields and on constants, with a call or a division, are
// computed once per particle before the kernels that reach them: pure calls
// (bodies without side effects, loops or mutable state; <cmath>), const
// globals, a parameter every call binds to the same const global, locals never
// modified. Anything else stays in the loop.
// RUN: %wash --dump-model %s 2>/dev/null | FileCheck %s
// Found, then kept by the plan.
// RUN: %wash --dump-after=find-hoistable %s 2>/dev/null | FileCheck %s --check-prefix=FOUND
#include <wash/wash.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

constexpr double rho0 = 1000.0;
const double stiffness = 3.0;
double mutableScale = 2.0;

struct Scheme {
  double gamma;
};
constexpr Scheme scheme{1.4};
constexpr Scheme other{1.67};

double eos(double rho) { return stiffness * (rho - rho0); }
double logged(double rho) {
  std::printf("%g\n", rho);
  return rho;
}
double scaled(double rho) { return mutableScale * rho; }
double looped(double rho) {
  for (int i = 0; i < 3; i++)
    rho *= 2;
  return rho;
}

// CHECK-LABEL: hoisted-per-neighbour: computed for every row before the kernel, read in its loop
// CHECK-NEXT:   Forces:
void pressure(wash::Particle &p, const std::vector<wash::Particle> &ns, const Scheme &s) {
  double sum = 0;
  for (const auto &n : ns) {
    const double rho = n.get_density();
    // CHECK-NEXT: hoisted_0 = eos(rho) @[[#@LINE+1]]:23 in pressure: depends only on constants and the fields of 'n': density
    const double pj = eos(rho);
    sum += pj;
    // CHECK-NEXT: hoisted_1 = std::sqrt(s.gamma * n.get_force_scalar("pressure") / rho) @[[#@LINE+1]]:12 in pressure: depends only on constants and the fields of 'n': density pressure
    sum += std::sqrt(s.gamma * n.get_force_scalar("pressure") / rho);
    // CHECK-NEXT: hoisted_2 = n.get_force_scalar("pressure") / (rho * rho) @[[#@LINE+1]]:12 in pressure: depends only on constants and the fields of 'n': density pressure
    sum += n.get_force_scalar("pressure") / (rho * rho);
    sum += n.get_mass() * 2.0;         // no call, no division: not worth a column
    sum += eos(p.get_density()) / rho; // reads the particle
    sum += logged(rho);                // a side effect
    sum += scaled(rho);                // a mutable global
    sum += looped(rho);                // a loop
    sum += rho / mutableScale;         // a mutable global
    auto f = [&] { return eos(n.get_density()); };
    sum += f(); // in a lambda
    for (const auto &m : ns) // two neighbours: only the part over one
      // CHECK-NEXT: hoisted_3 = eos(m.get_density()) @[[#@LINE+1]]:14 in pressure: depends only on constants and the fields of 'm': density
      sum += eos(m.get_density()) / n.get_density();
  }
  p.set_force_scalar("sum", sum);
}

// Called with two different constants: s is not one.
void twoSchemes(wash::Particle &p, const std::vector<wash::Particle> &ns, const Scheme &s) {
  double sum = 0;
  for (const auto &n : ns)
    sum += std::sqrt(s.gamma / n.get_density());
  p.set_force_scalar("sum", p.get_force_scalar("sum") + sum);
}

void Forces(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  pressure(p, ns, scheme);
  twoSchemes(p, ns, scheme);
  twoSchemes(p, ns, other);
}

// heat is written here and read through neighbours (a hazard): the loop
// reads a snapshot, so it stays as written.
// FOUND: hoisted_4 = eos(n.get_force_scalar("heat")) @[[#@LINE+5]]:10 in Relax: depends only on constants and the fields of 'n': heat
// CHECK-NOT: Relax
void Relax(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double h = 0;
  for (const auto &n : ns)
    h += eos(n.get_force_scalar("heat"));
  p.set_force_scalar("heat", h);
}

void Eos(wash::Particle &p) { p.set_force_scalar("pressure", eos(p.get_density())); }

void Spawn() {
  for (int i = 0; i < 4; i++)
    wash::create_particle(rho0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{});
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("pressure", 1);
  wash::add_force("sum", 1);
  wash::add_force("heat", 1);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Eos);
  wash::add_force_kernel(&Forces);
  wash::add_force_kernel(&Relax);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK-NOT: {{.}}
