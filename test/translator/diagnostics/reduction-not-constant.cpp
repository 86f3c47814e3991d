// A reduction kernel's variable must be a constant the translator can read.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>
#include <string>

double Height(const wash::Particle &p) { return p.get_pos().at(1); }

int main(int argc, char **argv) {
  std::string name = argc > 1 ? argv[1] : "top";
  wash::add_variable(name, 0.0);
  // CHECK: reduction-not-constant.cpp:[[@LINE+1]]:61: error: the variable of a reduction kernel must be a constant the translator can evaluate
  wash::add_reduction_kernel(&Height, wash::Reduction::Max, name);
  wash::start();
}
