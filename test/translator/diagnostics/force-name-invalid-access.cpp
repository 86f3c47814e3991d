// The force name rule holds at every accessor too, wherever the name is
// evaluated, and the error is at the name argument.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>
#include <string>

const std::string Spaced = "heat flow";

void Heat(wash::Particle &p) {
  // CHECK: force-name-invalid-access.cpp:[[@LINE+1]]:22: error: force name 'heat flow' is not an identifier;
  p.set_force_scalar(Spaced, 1.0);
  // CHECK: force-name-invalid-access.cpp:[[@LINE+1]]:49: error: force name 'mass' is a builtin particle property;
  p.set_force_scalar("heat", p.get_force_scalar("mass"));
  // CHECK: force-name-invalid-access.cpp:[[@LINE+1]]:22: error: force name 'for' is a C++ keyword;
  p.set_force_vector("for", p.get_vel());
  // CHECK: force-name-invalid-access.cpp:[[@LINE+1]]:22: error: force name 'co\x09ol' is not an identifier;
  p.set_force_scalar("co\tol", 1.0);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_update_kernel(&Heat);
  wash::start();
}
