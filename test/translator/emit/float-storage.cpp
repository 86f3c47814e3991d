// Float precision: float columns; reads convert to the API's double types and
// writes round to float, as the reference runtime's stores do, through
// wash::backend::rounded, which hides the float from g++'s SLP vectoriser.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/float-storage.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t/float-storage.serial.cpp | FileCheck %s
// HEADER: using Real = float;
// HEADER: using Stored = wash::Vec<Real, 2>;
// CHECK: wash_gen::P.heat[p] = wash::backend::rounded(wash_gen::Real(double(wash_gen::P.density[p]) * 2.0));
// CHECK: wash_gen::P.pos[p] = wash::backend::rounded(wash_gen::Stored(wash::ParticleVec(wash::ParticleVec(wash_gen::P.pos[p]) * 0.5)));
#include <wash/wash.hpp>

void Scale(wash::Particle& p) {
  p.set_force_scalar("heat", p.get_density() * 2.0);
  p.set_pos(p.get_pos() * 0.5);
}

int main() {
  wash::set_precision("float");
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Scale);
  wash::set_max_iterations(1);
  wash::start();
}
