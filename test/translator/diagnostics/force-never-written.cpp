// A force no kernel writes is zero wherever it is read: a read of one is an
// error, with the registered or written force of the closest name as a
// suggestion (a typo), and a note at its registration. Without a close name
// there is no suggestion; a registered force is no exception. A created force
// written and read (like the seed's) keeps only its warning.
// Diagnostics come pass by pass (ResolveFields' warnings first), fields in
// registration order.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error: --implicit-check-not=note: --implicit-check-not=warning:
#include <wash/wash.hpp>
#include <vector>

void Pressure(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  // CHECK-DAG: force-never-written.cpp:[[@LINE+1]]:33: warning: force 'drift' is used but never registered; it is created as a vector
  p.set_force_vector("drift", p.get_force_vector("drift") + p.get_vel());
  // CHECK-DAG: force-never-written.cpp:[[@LINE+1]]:15: error: force 'heat' is read but never written, so it is always zero{{$}}
  p.set_vel(p.get_force_vector("heat"));
  double sum = 0.0;
  for (const wash::Particle &n : ns)
    // CHECK-DAG: force-never-written.cpp:[[@LINE+2]]:14: warning: force 'presure' is used but never registered; it is created as a scalar
    // CHECK: force-never-written.cpp:[[@LINE+1]]:14: error: force 'presure' is read but never written, so it is always zero; did you mean 'pressure'?
    sum += n.get_force_scalar("presure");
  p.set_force_scalar("pressure", sum);
}

int main() {
  wash::set_influence_radius(0.5);
  // CHECK: force-never-written.cpp:[[@LINE+1]]:19: note: 'pressure' registered here
  wash::add_force("pressure", 1);
  wash::add_force("heat", 2);
  wash::add_force_kernel(&Pressure);
  wash::start();
}
