// The shared-memory search reorders only the columns whose old values can
// still be read: here density, set by Density on every path before anything
// reads it, stays in the old order (the backend type calls
// forEachReorderedColumn where the storage has it). A distributed backend
// moves every column: its storage has no such list.
// RUN: rm -rf %t && %wash --backend=serial -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/search-reorders-live-columns.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t/search-reorders-live-columns.serial.cpp | FileCheck %s
// RUN: rm -rf %t.m && %wash --backend=mpi -o %t.m %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=MPI --input-file %t.m/search-reorders-live-columns.wash.hpp
// HEADER:      /// Calls f(column) for every column a search's sort must reorder: not
// HEADER-NEXT: /// density, which every particle sets again after each
// HEADER-NEXT: /// search before anything reads them.
// HEADER-NEXT: template <typename F> void forEachReorderedColumn(F f) {
// HEADER-NEXT:   f(id);
// HEADER-NEXT:   f(pos);
// HEADER-NEXT:   f(vel);
// HEADER-NEXT:   f(mass);
// HEADER-NEXT:   f(smoothing_length);
// HEADER-NEXT: }
// CHECK: backend.search(P, at, box, wash::backend::HaloColumns<Kept, Fresh>{kept, fresh});
// MPI: template <typename F> void forEachColumn(F f) {
// MPI-NOT: forEachReorderedColumn
#include <wash/wash.hpp>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double sum = p.get_mass();
  for (const auto &n : ns)
    sum += n.get_mass();
  p.set_density(sum);
}

void Drift(wash::Particle &p) { p.set_pos(p.get_pos() + p.get_vel() * p.get_density()); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&Density);
  wash::add_update_kernel(&Drift);
  wash::set_max_iterations(1);
  wash::start();
}
