// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// The driver calls kernels by their plain name: a template kernel gave
// generated code that does not compile.
#include <wash/wash.hpp>

template <int N> void Update(wash::Particle &p) { p.set_mass(N); }

int main() {
  // CHECK: kernel-is-template.cpp:[[@LINE+1]]:3: error: kernel 'Update' is a function template specialization; kernels must be plain functions
  wash::add_update_kernel(&Update<2>);
  wash::start();
}
