// A hoisted per-neighbour expression gets a double column in the storage
// header; the driver computes it for every row (copies included) right after
// the search or refresh before each force kernel that reaches it, and the
// loop reads the column at the neighbour. The largest such expression is
// hoisted: cj * (...) takes cj's initialiser with it. With float storage the computation
// reads the same converted values the loop did.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/hoist-per-neighbour.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t/hoist-per-neighbour.serial.cpp | FileCheck %s
// RUN: %cxx_check -I%t %t/hoist-per-neighbour.serial.cpp
// RUN: rm -rf %t.f && %wash --backend=openmp -o %t.f %s -- -DFLOAT_STORAGE 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t.f/hoist-per-neighbour.openmp.cpp | FileCheck %s --check-prefix=FLOAT
// RUN: %cxx_check -I%t.f %t.f/hoist-per-neighbour.openmp.cpp
// HEADER: inline wash::backend::Column<double> hoisted_0; // sound_speed(s.gamma, rhoj) in pressure_terms
// HEADER-NEXT: inline wash::backend::Column<double> hoisted_1; // cj * (1.0 / (rhoj * rhoj)) in pressure_terms
// HEADER-NOT: hoisted_2
// CHECK: const double cj = double(wash_gen::hoisted_0[n]);
// CHECK-NEXT: sum += double(wash_gen::hoisted_1[n]) * std::sqrt(wash_gen::P.density[p]);
// CHECK-LABEL: // Density: force kernel, new neighbour search
// CHECK-NOT: hoisted_
// CHECK-LABEL: // Forces: force kernel, reuses the neighbour search of 'Density'
// CHECK-NEXT: // Neighbours read density, written since they were sent.
// CHECK-NEXT: backend.refresh([](auto send) { send(P.density); });
// CHECK-NEXT: // sound_speed(s.gamma, rhoj) (pressure_terms), once per row, not per pair.
// CHECK-NEXT: hoisted_0.resize(P.size());
// CHECK-NEXT: for (std::size_t row = 0; row < P.size(); ++row)
// CHECK-NEXT: hoisted_0[row] = ::sound_speed(::gas.gamma, wash_gen::P.density[row]);
// CHECK-NEXT: // cj * (1.0 / (rhoj * rhoj)) (pressure_terms), once per row, not per pair.
// CHECK-NEXT: hoisted_1.resize(P.size());
// CHECK-NEXT: for (std::size_t row = 0; row < P.size(); ++row)
// CHECK-NEXT: hoisted_1[row] = (::sound_speed(::gas.gamma, wash_gen::P.density[row]) * (1.0 / (wash_gen::P.density[row] * wash_gen::P.density[row])));
// CHECK-NEXT: backend.forEachParticle
// FLOAT: hoisted_0[row] = ::sound_speed(::gas.gamma, double(wash_gen::P.density[row]));
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

struct Gas {
  double gamma;
};
constexpr Gas gas{5.0 / 3.0};

double sound_speed(double gamma, double rho) { return std::sqrt(gamma * rho); }

void pressure_terms(wash::Particle &p, const std::vector<wash::Particle> &ns, const Gas &s) {
  double sum = 0;
  for (const auto &n : ns) {
    const double rhoj = n.get_density();
    const double cj = sound_speed(s.gamma, rhoj);
    sum += cj * (1.0 / (rhoj * rhoj)) * std::sqrt(p.get_density());
  }
  p.set_force_scalar("sum", sum);
}

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double rho = p.get_mass();
  for (const auto &n : ns)
    rho += n.get_mass();
  p.set_density(rho);
}

void Forces(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  pressure_terms(p, ns, gas);
}

void Spawn() {
  for (int i = 0; i < 4; i++)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{});
}

int main() {
#ifdef FLOAT_STORAGE
  wash::set_precision("float");
#endif
  wash::set_influence_radius(0.1);
  wash::add_force("sum", 1);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Forces);
  wash::set_max_iterations(1);
  wash::start();
}
