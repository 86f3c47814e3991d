// Nesting that clang's parser handles by recursion, with no bracket limit to
// stop it, is refused before parsing with a located error and exit status 1
// instead of a stack overflow: 100,000 prefix operators, 20,000 conditional
// operators in one statement, an else-if chain of 20,000 branches. Nested
// brackets are bounded by clang itself (-fbracket-depth, 256).
// RUN: rm -rf %t && mkdir -p %t
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) { p.set_mass(' + '- ' * 100000 + 'p.get_density()); }\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/minus.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/minus.cpp 2>&1 | FileCheck %s --check-prefix=PREFIX
// PREFIX: minus.cpp:2:40: error: too deeply nested: more than 1000 prefix operators in a row; wash (and clang's parser) cannot translate it: split it into smaller statements or functions
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) { p.set_mass(' + '!' * 100000 + 'p.get_density()); }\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/not.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/not.cpp 2>&1 | FileCheck %s --check-prefix=NOT
// NOT: not.cpp:2:40: error: too deeply nested: more than 1000 prefix operators in a row
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) { p.set_mass(' + '-(' * 100000 + 'p.get_density()' + ')' * 100000 + '); }\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/parens.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/parens.cpp 2>&1 | FileCheck %s --check-prefix=PARENS
// PARENS: parens.cpp:2:551: fatal error: bracket nesting level exceeded maximum of 256
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) {\n double x = p.get_density();\n p.set_mass(' + ''.join('x < %%d ? %%d :\n' %% (i, i) for i in range(20000)) + '0);\n}\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/conditional.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/conditional.cpp 2>&1 | FileCheck %s --check-prefix=COND
// COND: conditional.cpp:10004:11: error: too deeply nested: more than 10000 conditional operators in one statement
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) {\n double x = p.get_density();\n if (x < 0) p.set_mass(0);\n' + ''.join(' else if (x < %%d) p.set_mass(%%d);\n' %% (i, i) for i in range(1, 20000)) + '}\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/chain.cpp
// RUN: %expect_exit 1 %wash --dump-model %t/chain.cpp 2>&1 | FileCheck %s --check-prefix=CHAIN
// CHAIN: chain.cpp:16389:7: error: too deeply nested: an else-if chain of more than 16384 branches
// A chain within the limits translates.
// RUN: python3 -c "print('#include <wash/wash.hpp>\nvoid u(wash::Particle &p) {\n double x = p.get_density();\n if (x < 0) p.set_mass(0);\n' + ''.join(' else if (x < %%d) p.set_mass(%%d);\n' %% (i, i) for i in range(1, 500)) + ' p.set_mass(- - - - - - - - x);\n}\nint main() { wash::add_update_kernel(&u); wash::start(); }')" > %t/fine.cpp
// RUN: %expect_exit 0 %wash --dump-model %t/fine.cpp 2>&1 | FileCheck %s --check-prefix=FINE
// FINE: own-writes: mass
