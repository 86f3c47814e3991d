// A force name is a column name in every output file and an identifier in the
// generated code: it must be an identifier that is not a C++ keyword, a macro
// or a builtin particle property. The error is at the name.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>

#define SPEED 2.0

void Move(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel()); }

int main() {
  wash::set_influence_radius(0.5);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'heat wave' is not an identifier; a force name is an identifier ([A-Za-z_][A-Za-z0-9_]*) that is not a C++ keyword, a macro or a builtin particle property
  wash::add_force("heat wave", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'a"b' is not an identifier;
  wash::add_force("a\"b", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'line\x0abreak' is not an identifier;
  wash::add_force("line\nbreak", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name '2nd' is not an identifier;
  wash::add_force("2nd", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name '' is empty;
  wash::add_force("", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:26: error: force name 'density' is a builtin particle property;
  wash::add_force(/*x=*/ "density", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'id' is a builtin particle property;
  wash::add_force("id", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'class' is a C++ keyword;
  wash::add_force("class", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'and' is a C++ keyword;
  wash::add_force("and", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'SPEED' is a macro;
  wash::add_force("SPEED", 1);
  // CHECK: force-name-invalid.cpp:[[@LINE+1]]:19: error: force name 'WASH_DIM' is a macro;
  wash::add_force("WASH_DIM", 1);
  // Fine: an identifier nothing else uses, even one the generated struct has.
  wash::add_force("size", 1);
  wash::add_force("_heat2", 1);
  wash::add_update_kernel(&Move);
  wash::start();
}
