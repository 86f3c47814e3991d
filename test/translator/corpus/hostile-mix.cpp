// Odd but valid C++ around the API: null and self-referential kernels,
// templates, macros, a kernel registered twice, main as a kernel.
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>
#define SET(p, v) (p).set_mass(v)

template <typename T> void tmpl(wash::Particle &p) { SET(p, T(1)); }
void selfish(wash::Particle &p) { wash::add_update_kernel(&selfish); }

int main() {
  wash::add_update_kernel(nullptr);
  wash::add_update_kernel(&tmpl<int>);
  wash::add_update_kernel(&tmpl<int>);
  wash::add_update_kernel(&selfish);
  wash::add_init_kernel(reinterpret_cast<wash::InitKernel>(&main));
  wash::start();
}
// CHECK-DAG: hostile-mix.cpp:11:27: error: kernel must name a function
// CHECK-DAG: hostile-mix.cpp:8:35: error: call to 'wash::add_update_kernel' is not reached from 'main'
// CHECK-DAG: hostile-mix.cpp:15:25: error: init kernel 'main' has type 'int ()' but must have type 'void ()'
