// Helpers calling helpers twice, 40 levels deep: 2^40 paths, which the
// analysis must not walk one by one.
// RUN: python3 -c "print('#include <wash/wash.hpp>\ndouble f0(const wash::Particle &p) { return p.get_mass(); }\n' + ''.join('double f%%d(const wash::Particle &p) { return f%%d(p) + f%%d(p); }\n' %% (i, i - 1, i - 1) for i in range(1, 41)) + 'void u(wash::Particle &p) { p.set_density(f40(p)); }\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t.cpp
// RUN: %expect_exit 0 %wash --dump-model %t.cpp 2>&1 | FileCheck %s
// CHECK: own-reads: mass
