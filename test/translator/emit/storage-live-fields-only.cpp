// Storage: one column per live field, in the model's order; a registered
// force nothing reads or writes, and acc, get none.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --input-file %t/storage-live-fields-only.wash.hpp
// CHECK: // Fields with no storage (nothing reads or writes them): acc, unused.
// CHECK: using Real = double;
// CHECK: struct Particles {
// CHECK-NEXT:   wash::backend::Column<std::uint64_t> id;
// CHECK-NEXT:   wash::backend::Column<Stored> pos;
// CHECK-NEXT:   wash::backend::Column<Stored> vel;
// CHECK-NEXT:   wash::backend::Column<Real> density;
// CHECK-NEXT:   wash::backend::Column<Real> mass;
// CHECK-NEXT:   wash::backend::Column<Real> smoothing_length;
// CHECK-NEXT:   wash::backend::Column<Real> heat; // output only
// CHECK-EMPTY:
// CHECK-NOT: unused
#include <wash/wash.hpp>
#include <vector>

void Sum(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  double d = 0;
  for (const auto& n : ns)
    d += n.get_density();
  p.set_force_scalar("heat", d);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("unused", 1);
  wash::add_force("heat", 1);
  wash::add_force_kernel(&Sum);
  wash::set_max_iterations(1);
  wash::start();
}
