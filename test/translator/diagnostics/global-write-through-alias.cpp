// Writes reaching a global through pointers, iterators and references set
// anywhere in the function, and through pointers a global holds.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <functional>
#include <utility>
#include <vector>

double G = 0;
double Cells[4];
std::vector<double> Sums(4);
struct Node { double value; Node *next; double *slot; };
Node Head{0, nullptr, &G};
Node *First = &Head;

double &slot() { return Cells[2]; }
double *cell(int i) { return &Cells[i]; }

void Alias(wash::Particle &p) {
  double *q;
  double local = 0;
  q = &local;
  q = &G; // Set after its declaration.
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Alias' writes 'G'
  *q = p.get_mass();
  double *r = nullptr;
  if (p.get_mass() > 1)
    r = Cells + 1;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Alias' writes 'Cells'
  r[0] = 2;
  auto it = Sums.begin();
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Alias' writes 'Sums'
  *(it + 1) = 3;
  for (double &c : Cells)
    // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:5: error: update kernel 'Alias' writes 'Cells'
    c = 0;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Alias' writes 'Cells'
  slot() = 1;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Alias' writes 'Cells'
  *cell(3) += 1;
}

void Chain(wash::Particle &p, const std::vector<wash::Particle> &) {
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: force kernel 'Chain' writes 'First'
  First->next->value = p.get_density();
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: force kernel 'Chain' writes 'Head'
  *Head.slot = 1;
  Node *n = First;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: force kernel 'Chain' writes 'First'
  n->value = 2;
}

std::pair<double, double> Range;
void Indirect(wash::Particle &p) {
  auto &[low, high] = Range;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Indirect' writes 'Range'
  low = p.get_mass();
  std::vector<double *> slots{&G};
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Indirect' writes 'G'
  *slots[0] = 1;
  double *q = nullptr;
  double **qq = &q;
  *qq = &G;
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Indirect' writes 'G'
  *q = 5;
  std::reference_wrapper<double> r = std::ref(G);
  // CHECK: global-write-through-alias.cpp:[[@LINE+1]]:3: error: update kernel 'Indirect' writes 'G'
  r.get() = high;
}

int main() {
  wash::add_update_kernel(&Alias);
  wash::add_force_kernel(&Chain);
  wash::add_update_kernel(&Indirect);
  wash::start();
}
