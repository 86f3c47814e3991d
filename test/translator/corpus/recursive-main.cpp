// main calling itself and helpers calling each other while registering:
// rejected, not a crash or a hang (registrations must run exactly once).
// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
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
// CHECK: recursive-main.cpp:7:43: error: call to 'wash::add_force' is in 'a', which calls itself recursively
// CHECK: recursive-main.cpp:12:3: error: 'wash::start' may run more than once (in 'main', which calls itself recursively)
