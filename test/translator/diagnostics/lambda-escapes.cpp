// RUN: %expect_exit 1 %wash --dump-model %s 2>&1 | FileCheck %s
// A lambda run by a std::thread: its write was dropped.
#include <wash/wash.hpp>
#include <thread>

void Update(wash::Particle &p) {
  // CHECK: lambda-escapes.cpp:[[@LINE+1]]:17: error: lambda using a particle is stored or passed where the translator cannot follow its calls; call it directly or pass it to a standard algorithm
  std::thread t([&p] { p.set_mass(3); });
  t.join();
}

int main() {
  wash::add_update_kernel(&Update);
  wash::start();
}
