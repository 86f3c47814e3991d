// The user's macros do not reach the generated header or driver: names like
// Real, Index or step are hidden there (#pragma push_macro / #undef) and
// restored for the user's code after the header.
// RUN: rm -rf %t
// RUN: %wash --backend=serial -o %t %s
// RUN: FileCheck %s < %t/user-macros-hidden.wash.hpp
// RUN: %cxx_check -I%t %t/user-macros-hidden.serial.cpp
// RUN: %wash --backend=mpi -o %t/mpi %s
// RUN: %cxx_check -I%t/mpi %t/mpi/user-macros-hidden.mpi.cpp
#define Real float
#define Index int
#define Stored long
#define Backend struct
#include <wash/wash.hpp>

#define step 7
#define run(x) x
#define backend oops
#define i 2
#define self this

Real halve(Real x) { return x / 2; }

void Step(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  Index count = 0;
  for (const auto &q : ns)
    count += q.get_mass() > 0;
  p.set_density(halve(Real(count)) + step + i + run(1));
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force_kernel(&Step);
  wash::set_max_iterations(1);
  wash::start();
}
// CHECK:      #pragma once
// CHECK-NEXT: #pragma push_macro("Real")
// CHECK-NEXT: #undef Real
// CHECK:      #pragma pop_macro("Real")
