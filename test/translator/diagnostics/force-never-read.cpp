// A force written but never read is only output, which is fine (the seed's
// 'viscosity'), unless a force read and written elsewhere has a close name:
// then the write is likely a typo for it, and a warning says so.
// RUN: %wash --dump-model %s 2>&1 >/dev/null | FileCheck %s --implicit-check-not=error: --implicit-check-not=warning:
#include <wash/wash.hpp>

void Heat(wash::Particle &p) {
  p.set_force_scalar("temperature", p.get_force_scalar("temperature") + 1.0);
  p.set_force_scalar("output", 2.0 * p.get_force_scalar("temperature"));
}

void Cool(wash::Particle &p) {
  // CHECK: force-never-read.cpp:[[@LINE+1]]:5: warning: force 'temprature' is written but never read; did you mean 'temperature'?
  p.set_force_scalar("temprature", p.get_force_scalar("temperature") - 0.5);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("temperature", 1);
  wash::add_force("output", 1);
  wash::add_force("temprature", 1);
  wash::add_update_kernel(&Heat);
  wash::add_update_kernel(&Cool);
  wash::start();
}
