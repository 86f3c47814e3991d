// Force names may be constants the translator can evaluate, not only literals.
// RUN: %wash --dump-model %s | FileCheck %s
#include <wash/wash.hpp>

#include <string>

constexpr const char *kHeat = "heat";
const std::string kCold = "cold";

void update(wash::Particle &p) {
  p.set_force_scalar(kHeat, p.get_force_scalar(kCold) + 1), p.set_force_scalar(kCold, 0.0);
}

int main() {
  wash::add_force(kHeat, 1);
  wash::add_force(kCold, 1);
  wash::add_update_kernel(&update);
  wash::start();
}
// CHECK:      heat: registered scalar live output-only @15:19
// CHECK-NEXT: cold: registered scalar live @16:19
// CHECK:      0: update update
// CHECK-NEXT:   own-reads: cold
// CHECK-NEXT:   own-writes: heat cold
