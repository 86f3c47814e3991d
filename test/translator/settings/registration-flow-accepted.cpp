// RUN: %wash --dump-model %s 2>&1 | FileCheck %s
// Conditional settings, and registrations guarded by exactly what guards
// wash::start, are accepted: whenever the run starts, each registration ran
// once.
#include <wash/wash.hpp>
#include <cstdio>
#include <stdexcept>

void Fast(wash::Particle &p) { p.set_mass(1); }
void Slow(wash::Particle &p) { p.set_mass(2); }

void setup() {
  wash::add_force("f", 1);
  return;
}

int main(int argc, char **argv) {
  if (argc > 1)
    wash::set_simulation_name(argv[1]);
  else
    wash::set_simulation_name("default");
  argc > 2 ? wash::set_max_iterations(5) : wash::set_max_iterations(10);
  if (argc > 3) {
    std::fprintf(stderr, "usage\n");
    return 2;
  }
  try {
    setup();
    wash::add_update_kernel(&Fast);
    wash::start();
  } catch (const std::exception &e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}

// CHECK-NOT: error:
// CHECK: kernels
// CHECK-NEXT: 0: update Fast @[[@LINE-11]]:5
// CHECK-NOT: update Slow
