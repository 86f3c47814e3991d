// main calling helpers that call helpers twice, 20 levels deep: main's walk
// inlines every call (registrations count per call), so 2^20 bodies, more
// than the program's one budget. The translation stops with a located error
// rather than accepting main half-checked.
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) { p.set_density(1.0); }\nvoid f0() {}\n' + ''.join('void f%%d() { f%%d(); f%%d(); }\n' %% (i, i - 1, i - 1) for i in range(1, 21)) + 'int main() {\n  f20();\n  wash::add_update_kernel(&u);\n  wash::start();\n}')" > %t.cpp
// RUN: %expect_exit 1 %wash --dump-model %t.cpp 2>&1 | FileCheck %s
// CHECK: .cpp:{{[0-9]+}}:{{[0-9]+}}: error: main calls functions too many times for the translator to follow (the translation walks at most 200000 function bodies)
// CHECK-NOT: error:
