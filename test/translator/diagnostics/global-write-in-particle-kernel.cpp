// Global and static state written per particle: order- and rank-dependent.
// RUN: rm -rf %t
// RUN: %expect_exit 1 %wash --backend=serial -o %t %s 2>&1 | FileCheck %s --implicit-check-not=error:
// RUN: test ! -e %t
#include <wash/wash.hpp>
#include <random>
#include <vector>

int Visited = 0;
double Total[2];
std::vector<double> Seen;
std::mt19937 Rng(1);
struct Stats { static double Max; };
double Stats::Max = 0;
const double Scale = 2.0; // Read only: fine.
double Gain = 1.0;        // Set in main, read in kernels: fine.

void count() {
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Update' writes 'Visited', a global or static variable; it runs once per particle, in an order that differs between backends and ranks, so the result is not the same everywhere
  ++Visited;
}

void Update(wash::Particle &p) {
  count();
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Update' writes 'Total'
  Total[0] += p.get_mass();
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Update' writes 'Seen'
  Seen.push_back(p.get_mass());
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:19: error: update kernel 'Update' writes 'Rng'
  double jitter = Rng() * 1e-12;
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Update' writes 'Stats::Max'
  Stats::Max = p.get_mass();
  static int Calls = 0;
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Update' writes 'Calls'
  Calls++;
  p.set_mass(p.get_mass() * Scale * Gain + jitter);
}

void Force(wash::Particle &p, const std::vector<wash::Particle> &) {
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: force kernel 'Force' writes 'Gain'
  Gain = p.get_density();
}

double *Cursor = Total;
void Aliases(wash::Particle &p, const std::vector<wash::Particle> &) {
  double &sum = Total[1];
  double *count = &Total[0];
  double local = 0;
  double &mine = local; // An alias of a local: fine.
  mine += 1;
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: force kernel 'Aliases' writes 'Total'
  sum += p.get_density();
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: force kernel 'Aliases' writes 'Total'
  *count = 1;
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: force kernel 'Aliases' writes 'Cursor'
  *Cursor = local;
}

double Height(const wash::Particle &p) {
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: reduction kernel 'Height' writes 'Visited'
  Visited = 1;
  return p.get_mass();
}

// Constructors and destructors run in the kernel too.
struct Tally {
  int &into;
  explicit Tally(int &n) : into(n) {}
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:29: error: update kernel 'Scoped' writes 'Visited'
  Tally() : into(Visited) { ++Visited; }
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:14: error: update kernel 'Scoped' writes 'Total'
  ~Tally() { Total[1] = 0; }
};
struct Counter {
  int &n;
  explicit Counter(int &c) : n(c) {}
  void add() { ++n; } // Through what the object holds.
};
void Scoped(wash::Particle &p) {
  Tally t;
  Counter held(Visited); // Binds, writes nothing yet.
  // CHECK: global-write-in-particle-kernel.cpp:[[@LINE+1]]:3: error: update kernel 'Scoped' passes 'Visited', a global or static variable, to 'Counter::add'
  held.add();
  int local = 0;
  Counter mine(local); // A local: fine.
  mine.add();
  p.set_mass(p.get_mass() + local);
}

int Spawned = 0;
void Init() {
  Spawned = 1; // Init kernels run once: fine.
}

int main(int argc, char **) {
  Gain = argc;
  wash::add_variable("h", 0.0);
  wash::add_init_kernel(&Init);
  wash::add_update_kernel(&Update);
  wash::add_force_kernel(&Force);
  wash::add_force_kernel(&Aliases);
  wash::add_reduction_kernel(&Height, wash::Reduction::Max, "h");
  wash::add_update_kernel(&Scoped);
  wash::start();
}
