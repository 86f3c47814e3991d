// A force named `linux` (or `unix`): under -std=gnu++20 these are macros
// (1), so the generated project builds as standard C++20, as the translator
// and its compile gate parse it: CMakeLists.txt turns CMAKE_CXX_EXTENSIONS
// off, and the gate accepts the program.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>&1 | count 0
// RUN: FileCheck %s < %t/CMakeLists.txt
// RUN: %cxx_check -I%t %t/force-named-linux.serial.cpp
// RUN: not %cxx_check -std=gnu++20 -I%t %t/force-named-linux.serial.cpp
// CHECK: set(CMAKE_CXX_EXTENSIONS OFF)
// CHECK: add_executable(
#include <wash/wash.hpp>

void Heat(wash::Particle &p) {
  p.set_force_scalar("linux", p.get_force_scalar("linux") + 1.0);
  p.set_force_scalar("unix", p.get_force_scalar("unix") + p.get_force_scalar("linux"));
}

int main() {
  wash::set_influence_radius(0.5);
  wash::add_force("linux", 1);
  wash::add_force("unix", 1);
  wash::add_update_kernel(&Heat);
  wash::start();
}
