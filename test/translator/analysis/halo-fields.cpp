// Before a force kernel, halo particles need pos and what the kernel reads
// through neighbours; own-only reads (mass) need not travel.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

void kernel(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = p.get_mass();
  for (const auto &n : ns)
    s += n.get_density() + n.get_force_scalar("t");
  p.set_force_scalar("t", s);
}

int main() {
  wash::add_force("t", 1);
  wash::add_force_kernel(&kernel);
  wash::start();
}
// CHECK:      own-reads: mass
// CHECK:      halo: pos density t
// CHECK:      halo-exchange (new rows): pos density t
// Kept halo rows: density is not written, t is.
// CHECK-NEXT: halo-exchange (rows kept from the previous search): pos t{{$}}
