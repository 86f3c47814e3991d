// Every write to standard output is checked: a model printed to a full
// device (or any failed write) is an error and exit status 1, not a silent 0.
// RUN: not %wash --dump-model %s > /dev/full 2> %t.err
// RUN: FileCheck %s < %t.err
// RUN: not %wash --dump-after=collect-simulation %s > /dev/full 2> %t.err
// RUN: FileCheck %s < %t.err
// RUN: not %wash --dump-after=help > /dev/full 2> %t.err
// RUN: FileCheck %s < %t.err
// CHECK: wash: error: cannot write to standard output: No space left on device
// RUN: %wash --dump-model %s | FileCheck %s --check-prefix=WRITTEN
// WRITTEN: max-iterations: 1
#include <wash/wash.hpp>

void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
