// Variable names are checked at translation: a name no add_variable adds is
// an error at the name (the run would stop there), with the closest added
// name as a suggestion. This holds in every function of the program, in
// get_variable, set_variable and a reduction kernel's variable.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

const char *const kSpeed = "spead";

void Move(wash::Particle &p) {
  // CHECK: variable-unknown.cpp:[[@LINE+1]]:60: error: variable 'dT' is never added with wash::add_variable; did you mean 'dt'?
  p.set_pos(p.get_pos() + p.get_vel() * wash::get_variable("dT"));
}

double Height(const wash::Particle &p) { return p.get_pos().at(1); }

void Tick() {
  // CHECK: variable-unknown.cpp:[[@LINE+1]]:22: error: variable 'time' is never added with wash::add_variable{{$}}
  wash::set_variable("time", wash::get_variable("dt") + 1.0);
  // CHECK: variable-unknown.cpp:[[@LINE+1]]:22: error: variable 'spead' is never added with wash::add_variable; did you mean 'speed'?
  wash::set_variable(kSpeed, 1.0);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_variable("dt", 0.01);
  wash::add_variable("speed", 0.0);
  wash::add_update_kernel(&Move);
  wash::add_void_kernel(&Tick);
  // CHECK: variable-unknown.cpp:[[@LINE+1]]:61: error: variable 'heigth' is never added with wash::add_variable{{$}}
  wash::add_reduction_kernel(&Height, wash::Reduction::Max, "heigth");
  wash::start();
}
