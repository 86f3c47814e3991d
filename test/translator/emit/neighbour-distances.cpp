// Where the search keeps distances, the neighbour list type says so and the
// magnitudes read them: plainly for a `wash::Particle &` parameter, behind a
// compile-time test for a generic (const reference) one, which is a
// neighbour in some calls. With float positions (the user's magnitude is then
// float, the search's double) or a force kernel moving its particle, nothing
// changes.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/neighbour-distances.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t/neighbour-distances.serial.cpp | FileCheck %s
// RUN: rm -rf %t.f && %wash --backend=openmp -o %t.f %s -- -DFLOAT_POSITIONS 2>/dev/null
// RUN: FileCheck %s --check-prefix=PLAIN-HEADER --input-file %t.f/neighbour-distances.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t.f/neighbour-distances.openmp.cpp | FileCheck %s --check-prefix=PLAIN
// RUN: rm -rf %t.m && %wash --backend=mpi -o %t.m %s -- -DMOVES 2>/dev/null
// RUN: FileCheck %s --check-prefix=PLAIN-HEADER --input-file %t.m/neighbour-distances.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t.m/neighbour-distances.mpi.cpp | FileCheck %s --check-prefix=PLAIN
// HEADER: using NeighbourList = wash::backend::Neighbours<2, Stored, NeighbourRef, true>;
// HEADER: inline constexpr bool isSelf = std::is_same_v<std::remove_cvref_t<T>, Self>;
// PLAIN-HEADER: using NeighbourList = wash::backend::Neighbours<2, Stored, NeighbourRef>;
// PLAIN-HEADER-NOT: isSelf
// CHECK: for (const auto &n : ns) sum += W((wash_gen::isSelf<decltype(q)> ? ns.distance(n) : (wash_gen::P.pos[q] - wash_gen::P.pos[n]).magnitude()));
// CHECK: double r = ns.distance(n);
// PLAIN-NOT: distance(
#include <wash/wash.hpp>
#include <vector>

double W(double r) { return r < 0.1 ? 0.1 - r : 0.0; }

double around(const wash::Particle &q, const std::vector<wash::Particle> &ns) {
  double sum = 0;
  for (const auto &n : ns) sum += W((q.get_pos() - n.get_pos()).magnitude());
  return sum;
}

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_density(around(p, ns));
}

void Spread(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec2D pos = p.get_pos();
  double sum = 0;
  for (const auto &n : ns) {
    wash::Vec2D d = pos - n.get_pos();
    double r = d.magnitude();
    sum += W(r) * around(n, ns);
  }
  p.set_mass(sum);
#ifdef MOVES
  p.set_pos(pos);
#endif
}

int main() {
#ifdef FLOAT_POSITIONS
  wash::set_precision("float");
#endif
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Spread);
  wash::set_max_iterations(1);
  wash::start();
}
