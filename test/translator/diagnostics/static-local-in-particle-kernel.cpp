// Function-local statics of a kernel and of the helpers it reaches are
// shared by every particle, like globals.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <vector>

double smoothed(double x) {
  static double Last = 0;
  // CHECK-DAG: static-local-in-particle-kernel.cpp:[[@LINE+1]]:3: error: reduction kernel 'Peak' writes 'Last'
  Last = 0.5 * (Last + x);
  return Last;
}

struct Table {
  static std::vector<double> &cache() {
    static std::vector<double> Values;
    return Values;
  }
};

void bump(int &n) { ++n; }

double Peak(const wash::Particle &p) {
  static int Calls = 0;
  // CHECK-DAG: static-local-in-particle-kernel.cpp:[[@LINE+1]]:8: error: reduction kernel 'Peak' passes 'Calls', a global or static variable, to 'bump'
  bump(Calls);
  // CHECK-DAG: static-local-in-particle-kernel.cpp:[[@LINE+1]]:3: error: reduction kernel 'Peak' writes 'Values'
  Table::cache().push_back(p.get_mass());
  static const double Scale = 2; // Read only: fine.
  return smoothed(p.get_mass()) * Scale;
}

int main() {
  wash::add_variable("peak", 0.0);
  wash::add_reduction_kernel(&Peak, wash::Reduction::Max, "peak");
  wash::start();
}
