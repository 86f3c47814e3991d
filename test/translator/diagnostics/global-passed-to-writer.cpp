// A global bound to a parameter through which the callee may write: a
// helper's reference or pointer it writes through, or any non-const
// reference or pointer parameter of library code.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <algorithm>
#include <functional>
#include <iterator>
#include <utility>
#include <vector>

int Hits = 0;
double Low = 0, High = 1;
double Bins[8];
std::vector<double> Samples;

void bump(int &n) { ++n; }
void store(double *into, double x) { *into = x; }
void forward(int &n) { bump(n); } // Reported where the global is passed.
void keep(std::vector<double> &v, double x) { v.push_back(x); }

template <class T> void twice(T &x) { x *= 2; }
void (*Hook)(double &) = nullptr;
std::function<void(double &)> Callback;

void Spread(wash::Particle &p, const std::vector<wash::Particle> &) {
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:8: error: force kernel 'Spread' passes 'Hits', a global or static variable, to 'bump', which may change it through a non-const reference or pointer; the kernel runs once per particle, in an order that differs between backends and ranks, so the result is not the same everywhere
  bump(Hits);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:11: error: force kernel 'Spread' passes 'Hits', a global or static variable, to 'forward'
  forward(Hits);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:9: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'store'
  store(&Bins[1], p.get_density());
  double *last = Bins;
  last = last + 7;
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:9: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'store'
  store(last, 1);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:8: error: force kernel 'Spread' passes 'Samples', a global or static variable, to 'keep'
  keep(Samples, 1);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+2]]:13: error: force kernel 'Spread' passes 'Low', a global or static variable, to 'std::swap'
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:18: error: force kernel 'Spread' passes 'High', a global or static variable, to 'std::swap'
  std::swap(Low, High);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:30: error: force kernel 'Spread' passes 'Hits', a global or static variable, to 'std::exchange'
  int before = std::exchange(Hits, 0);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+2]]:13: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'std::fill'
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:31: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'std::fill'
  std::fill(std::begin(Bins), std::end(Bins), 0.0);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+2]]:17: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'std::for_each'
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:23: error: force kernel 'Spread' passes 'Bins', a global or static variable, to 'std::for_each'
  std::for_each(Bins, Bins + 8, [](double &b) { b *= 2; });
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:9: error: force kernel 'Spread' passes 'Low', a global or static variable, to 'twice'
  twice(Low);
  auto zero = [](auto &x) { x = 0; };
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:8: error: force kernel 'Spread' passes 'High', a global or static variable, to 'Spread(wash::Particle &, const std::vector<wash::Particle> &)::(anonymous class)::operator()'
  zero(High);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:8: error: force kernel 'Spread' passes 'Low', a global or static variable, to 'a function called through a pointer'
  Hook(Low);
  // CHECK: global-passed-to-writer.cpp:[[@LINE+1]]:12: error: force kernel 'Spread' passes 'Low', a global or static variable, to 'std::function<void (double &)>::operator()'
  Callback(Low);
  p.set_mass(p.get_mass() + before);
}

int main() {
  wash::add_force_kernel(&Spread);
  wash::start();
}
