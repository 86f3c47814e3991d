// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

// CHECK: helper-not-defined.cpp:[[@LINE+4]]:3: error: 'external' receives a particle but is not defined in this translation unit, so its accesses cannot be seen
// CHECK: helper-not-defined.cpp:[[@LINE+1]]:6: note: 'external' declared here
void external(wash::Particle &p);
void update(wash::Particle &p) {
  external(p);
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
