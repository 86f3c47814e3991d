// The rewritten kernels name the generated storage (wash_gen::P) and
// particle type (wash_gen::Self) in the user's code, where a user macro of
// that name would replace them: an error at the macro, with where.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s
// RUN: test ! -e %t
#include <wash/wash.hpp>

// CHECK-DAG: macro-names-generated-code.cpp:[[@LINE+1]]:9: error: macro 'P' has the name of an identifier the generated code writes into this program; rename the macro
#define P 101325.0
// CHECK-DAG: macro-names-generated-code.cpp:[[@LINE+1]]:9: error: macro 'Self' has the name
#define Self Me

// CHECK-DAG: macro-names-generated-code.cpp:[[@LINE+1]]:13: note: the generated code writes 'Self' here
void Update(wash::Particle &p) {
  // CHECK-DAG: macro-names-generated-code.cpp:[[@LINE+1]]:3: note: the generated code writes 'P' here
  p.set_density(P / 1000.0);
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_update_kernel(&Update);
  wash::set_max_iterations(1);
  wash::start();
}
