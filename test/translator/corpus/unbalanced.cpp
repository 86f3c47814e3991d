// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// CHECK: error: expected '}'
#include <wash/wash.hpp>
void update(wash::Particle &p) { if (p.get_mass() > 0) { p.set_mass(1);
int main() { wash::add_update_kernel(&update); wash::start();
