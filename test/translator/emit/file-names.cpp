// Ordinary file names give a generated project that configures and builds:
// target names are sanitised (my_sim-serial), the source is quoted and
// escaped in CMakeLists.txt.
// REQUIRES: backend-serial
// RUN: python3 %S/../Inputs/build_file_names.py %wash %cxx %t "my sim" "sim (1)" "simulación" 'cost$5' "a;b" | FileCheck %s
// CHECK: my sim: built
// CHECK-NEXT: sim (1): built
// CHECK-NEXT: simulación: built
// CHECK-NEXT: cost$5: built
// CHECK-NEXT: a;b: built
// RUN: grep -h add_executable %t/project-*/CMakeLists.txt | FileCheck %s --check-prefix=CMAKE
// CMAKE: add_executable(my_sim-serial "my sim.serial.cpp")
// CMAKE: add_executable(sim__1_-serial "sim (1).serial.cpp")
// CMAKE: add_executable(simulaci__n-serial "simulación.serial.cpp")
// CMAKE: add_executable(cost_5-serial "cost\$5.serial.cpp")
// CMAKE: add_executable(a_b-serial "a\;b.serial.cpp")
