// setjmp/longjmp in the code main runs can jump back over registrations (they
// run twice) or out of them (they never run): the translator reads each once.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s --implicit-check-not=error:
#include <wash/wash.hpp>
#include <csetjmp>

static std::jmp_buf again;
static int tries = 0;

void Touch(wash::Particle &p) { p.set_mass(1.0); }

int main() {
  wash::set_influence_radius(0.5);
  // CHECK: registration-with-longjmp.cpp:[[@LINE+1]]:7: error: '{{_?}}setjmp' in code that registers with wash
  if (setjmp(again) == 0) {
  }
  wash::add_update_kernel(&Touch);
  // CHECK: registration-with-longjmp.cpp:[[@LINE+1]]:20: error: 'longjmp' in code that registers with wash
  if (++tries < 2) std::longjmp(again, 1);
  wash::start();
}
