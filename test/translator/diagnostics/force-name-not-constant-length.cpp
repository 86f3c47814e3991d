// std::string(s, n) keeps the first n characters of s: the translator does
// not evaluate it (it used to read the whole of s, a different force from the
// reference's), so the name is not a constant it can evaluate.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: %expect_exit 1 %wash --dump-model %s -- -DREGISTER 2>&1 | FileCheck %s --check-prefix=REG --implicit-check-not=error:
#include <wash/wash.hpp>
#include <string>

void Heat(wash::Particle &p) {
  // CHECK: force-name-not-constant-length.cpp:[[@LINE+1]]:22: error: force name must be a string literal or a constant the translator can evaluate
  p.set_force_scalar(std::string("heatwave", 4), 1.0);
}

int main() {
  wash::set_influence_radius(0.5);
#ifdef REGISTER
  // REG: force-name-not-constant-length.cpp:[[@LINE+1]]:19: error: force name must be a string literal or a constant the translator can evaluate
  wash::add_force(std::string("heatwave", 4), 1);
#endif
  wash::add_update_kernel(&Heat);
  wash::start();
}
