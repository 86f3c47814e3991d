// Deep expression nesting must not overflow the translator's stack.
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) { p.set_mass(' + '(1+' * 200 + '1' + ')' * 200 + ' + ' + ' + '.join(['p.get_density()'] * 5000) + '); }\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t.cpp
// RUN: %expect_exit 0 %wash --dump-model %t.cpp 2>&1 | FileCheck %s
// CHECK: own-reads: density
// CHECK: own-writes: mass
