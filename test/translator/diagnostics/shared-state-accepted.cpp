// What stays accepted: reading globals, passing them by value or const
// reference, locals passed by reference (a local engine included), init and
// void kernels changing globals, and kernels that opt in with
// wash::allow_shared_state(), a call dropped from the generated code.
// RUN: rm -rf %t
// RUN: %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --allow-empty --implicit-check-not=error: --implicit-check-not=warning:
// RUN: FileCheck --check-prefix=GEN %s < %t/shared-state-accepted.serial.cpp
#include <wash/wash.hpp>
#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

double Gain = 1.0;
const double Scale = 2.0;
double Weights[3] = {1, 2, 3};
std::vector<double> Table(8, 1.0);
std::mt19937 Gen(1);
int Steps = 0;
struct Node { double value; Node *next; };
Node Tail{1, nullptr};
Node *First = &Tail;

void bump(int &n) { ++n; }
double twice(const double &x) { return 2 * x; }
double sum(std::vector<double> v) { return std::accumulate(v.begin(), v.end(), 0.0); }
double draw(std::mt19937 &g) { return std::uniform_real_distribution<>(0.0, 1.0)(g); }
void scale(double *into, double by) { *into *= by; }

void Read(wash::Particle &p) {
  double total = 0;
  for (double w : Weights)
    total += w;
  for (double t : Table)
    total += t;
  total += Table[2] + Table.at(1) + *Table.begin() + First->next->value * 0 + First->value;
  total += std::accumulate(std::begin(Weights), std::end(Weights), 0.0);
  total += *std::max_element(Table.begin(), Table.end());
  total += std::max(Gain, Scale) + twice(Gain) + sum(Table) + std::as_const(Table)[0];
  p.set_mass(p.get_mass() * total);
}

void Local(wash::Particle &p, const std::vector<wash::Particle> &) {
  std::mt19937 gen(p.get_id());
  int n = 0;
  bump(n);
  double x = draw(gen) + std::uniform_real_distribution<>(0.0, 1.0)(gen);
  double local[2] = {x, 0};
  double *q = local;
  scale(q, 2);
  std::swap(local[0], local[1]);
  std::fill(std::begin(local), std::end(local), 1.0);
  p.set_density(p.get_density() + n + local[0]);
}

void Init() {
  Gain = std::rand();
  bump(Steps);
  std::swap(Weights[0], Weights[1]);
}

void Tick() {
  ++Steps;
  Table.push_back(draw(Gen));
}

void Deliberate(wash::Particle &p) {
  // GEN: (void)0 /* wash::allow_shared_state(): a marker for the translator */;
  wash::allow_shared_state();
  Gain += std::rand() * 0.0;
  bump(Steps);
  p.set_mass(p.get_mass() + draw(Gen) * 0.0);
}

int main() {
  wash::add_init_kernel(&Init);
  wash::add_update_kernel(&Read);
  wash::add_force_kernel(&Local);
  wash::add_void_kernel(&Tick);
  wash::add_update_kernel(&Deliberate);
  wash::start();
}
