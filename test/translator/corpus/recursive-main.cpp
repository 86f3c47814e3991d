// main calling itself and helpers calling each other while registering.
// RUN: %expect_exit 0 %wash --dump-model %s 2>&1 | FileCheck %s
#include <wash/wash.hpp>
void b(int n);
void a(int n) { if (n > 0) b(n - 1); }
void b(int n) { if (n > 0) a(n - 1); else wash::add_force("x", 1); }
int main(int argc, char **) {
  if (argc > 100)
    return main(argc - 1, nullptr);
  a(3);
  wash::start();
}
// CHECK: x: registered scalar dead @6:59
