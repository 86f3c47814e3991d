// RUN: %expect_exit 1 %wash --dump-model %s -- -isystem %S/../Inputs/library 2>&1 | FileCheck %s
#include <wash/wash.hpp>
#include <library_helpers.hpp>

// CHECK: helper-in-library-header.cpp:[[@LINE+3]]:17: error: 'LibraryMass' receives a particle but is defined in '{{.*}}library_helpers.hpp', a system or library header, which wash does not rewrite; include it with a quoted include or -I instead of -isystem, or move it into the simulation's own files
// CHECK: library_helpers.hpp:6:15: note: 'LibraryMass' declared here
void update(wash::Particle &p) {
  p.set_density(LibraryMass(p));
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
