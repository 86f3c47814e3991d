// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// Registrations that may be skipped when wash::start runs: the generated
// driver would make every one of them.
#include <wash/wash.hpp>
#include <stdexcept>

void Fast(wash::Particle &p) { p.set_mass(1); }
void Slow(wash::Particle &p) { p.set_mass(2); }

void ifElse(int argc) {
  if (argc > 1)
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_update_kernel' is inside an 'if'; registrations must run unconditionally, once, before 'wash::start'
    wash::add_update_kernel(&Fast);
  else
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_update_kernel' is inside an 'else'; registrations
    wash::add_update_kernel(&Slow);
}

void constantFalse() {
  if (false)
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_force' is inside an 'if'; registrations
    wash::add_force("never", 1);
}

bool registerIt() {
  // CHECK: registration-conditional.cpp:[[@LINE+1]]:3: error: call to 'wash::add_variable' is on the right of '&&'; registrations
  wash::add_variable("v", 0.0);
  return true;
}

void logical(int argc) {
  bool a = argc > 2 && registerIt();
  // CHECK: registration-conditional.cpp:[[@LINE+1]]:25: error: call to 'wash::add_force' is on the right of '||'; registrations
  bool b = argc > 3 || (wash::add_force("b", 1), true);
  // CHECK: registration-conditional.cpp:[[@LINE+1]]:20: error: call to 'wash::add_force' is in an operand of '?:'; registrations
  argc > 4 ? (void)wash::add_force("c", 1) : (void)0;
  (void)a, (void)b;
}

void selected(int argc) {
  switch (argc) {
  case 2:
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_force' is inside a 'switch'; registrations
    wash::add_force("d", 1);
    break;
  }
}

void mayThrow(int argc) {
  try {
    if (argc > 5)
      throw std::runtime_error("no");
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_force' is inside a 'try' block; registrations
    wash::add_force("e", 1);
  } catch (const std::exception &) {
    // CHECK: registration-conditional.cpp:[[@LINE+1]]:5: error: call to 'wash::add_force' is inside a 'catch' handler; registrations
    wash::add_force("f", 1);
  }
}

void earlyReturn(int argc) {
  if (argc > 6)
    return;
  // CHECK: registration-conditional.cpp:[[@LINE+1]]:3: error: call to 'wash::add_force' is after an early 'return'; registrations
  wash::add_force("g", 1);
}

int main(int argc, char **) {
  ifElse(argc);
  constantFalse();
  logical(argc);
  selected(argc);
  mayThrow(argc);
  earlyReturn(argc);
  wash::start();
}
