// Variable names known only at run time are left to the run: an add_variable
// with such a name could add any name, so no use is reported; a use with such
// a name is not checked either.
// RUN: %wash --dump-model %s 2>&1 >/dev/null | FileCheck %s --allow-empty --implicit-check-not=error:
#include <wash/wash.hpp>
#include <string>

void Tick() { wash::set_variable("anything", wash::get_variable("dt")); }

int main(int argc, char **argv) {
  wash::set_influence_radius(0.5);
  wash::add_variable(argc > 1 ? argv[1] : "anything", 0.0);
  wash::add_variable("dt", wash::get_variable(std::string(argc > 2 ? argv[2] : "anything")));
  wash::add_void_kernel(&Tick);
  wash::start();
}
