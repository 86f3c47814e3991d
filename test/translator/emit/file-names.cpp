// Ordinary file names give a generated project that configures and builds,
// with Ninja and with make: target names are sanitised (my_sim-serial), the
// source is quoted in CMakeLists.txt.
// REQUIRES: backend-serial
// RUN: python3 %S/../Inputs/build_file_names.py %wash %cxx %t "my sim" "simulación" | FileCheck %s
// CHECK: my sim: built
// CHECK-NEXT: simulación: built
// RUN: python3 %S/../Inputs/build_file_names.py "-GUnix Makefiles" %wash %cxx %t.make "sim (1) & it's #2, ~50% {x}=y!" | FileCheck %s --check-prefix=MAKE
// MAKE: sim (1) & it's #2, ~50% {x}=y!: built
// RUN: grep -h add_executable %t/project-*/CMakeLists.txt %t.make/project-*/CMakeLists.txt | FileCheck %s --check-prefix=CMAKE
// CMAKE: add_executable(my_sim-serial "my sim.serial.cpp")
// CMAKE: add_executable(simulaci__n-serial "simulación.serial.cpp")
// CMAKE: add_executable(sim__1____it_s__2___50___x__y_-serial "sim (1) & it's #2, ~50% {x}=y!.serial.cpp")
//
// Names that no quoting gets through CMake, make and Ninja alike (or through
// the C++ strings naming the generated files) are refused at translation,
// with the reason, before anything is written or expanded.
// RUN: python3 %S/../Inputs/build_file_names.py %wash %cxx %t.bad "a;b" 'q"uote' 'a\tb' 'a\nb' 'x$(touch expanded)' 'c$5' 'a:b' 'a|b' 'a[1]' 'back\slash' | FileCheck %s --check-prefix=REFUSED
// REFUSED: a;b: translate failed: wash: error: cannot translate '{{.*}}a;b.cpp': its name contains ';', which the generated project's build (CMake, make, Ninja) cannot name: rename the file (letters, digits, spaces and ._+-() are safe)
// REFUSED-NEXT: q"uote: translate failed: {{.*}}: its name contains '"', which
// REFUSED-NEXT: a\tb: translate failed: {{.*}}: its name contains a tab, which
// REFUSED-NEXT: a\nb: translate failed: {{.*}}: its name contains a line break, which
// REFUSED-NEXT: x$(touch expanded): translate failed: {{.*}}: its name contains '$', which
// REFUSED-NEXT: c$5: translate failed: {{.*}}: its name contains '$', which
// REFUSED-NEXT: a:b: translate failed: {{.*}}: its name contains ':', which
// REFUSED-NEXT: a|b: translate failed: {{.*}}: its name contains '|', which
// REFUSED-NEXT: a[1]: translate failed: {{.*}}: its name contains '[', which
// REFUSED-NEXT: back\slash: translate failed: {{.*}}: its name contains '\', which
// RUN: not ls %t.bad/expanded %t.bad/project-4/expanded
// RUN: not ls %t.bad/project-0
// --dump-model writes no project: any name is fine.
// RUN: cp %s '%t.bad/a;b.cpp' && %wash --dump-model '%t.bad/a;b.cpp' | FileCheck %s --check-prefix=DUMP
// DUMP: max-iterations: 1
#include <wash/wash.hpp>

void Heat(wash::Particle& p) { p.set_density(p.get_density() * 2.0); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_update_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
