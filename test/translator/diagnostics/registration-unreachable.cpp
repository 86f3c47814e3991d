// Registrations the walk from main cannot see: in a function main never
// calls, and in a kernel.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>

void setup() {
  // CHECK: registration-unreachable.cpp:[[@LINE+1]]:3: error: call to 'wash::add_force' is not reached from 'main'; the translator only sees registrations that 'main' makes directly or through the functions it calls
  wash::add_force("heat", 1);
}

void update(wash::Particle &p) {
  // CHECK: registration-unreachable.cpp:[[@LINE+1]]:3: error: call to 'wash::set_max_iterations' is not reached from 'main'
  wash::set_max_iterations(3);
}

int main() {
  wash::add_update_kernel(&update);
  wash::start();
}
