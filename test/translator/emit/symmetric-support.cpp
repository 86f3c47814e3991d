// Under the symmetric smoothing-length rule (wash::Support::Symmetric) a
// search reads every candidate's smoothing length: the geometry says so, the
// halo (and each new search's columns) carries smoothing_length, and the
// program checks that main asks for the rule it was translated for.
// RUN: rm -rf %t && %wash --backend=openmp -o %t/omp %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/omp/symmetric-support.openmp.cpp | FileCheck %s
// RUN: %wash --backend=mpi -o %t/mpi %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/mpi/symmetric-support.mpi.cpp | FileCheck %s --check-prefix=MPI
// CHECK: .floatStorage = false, .smoothingLengthSearch = true, .symmetricSupport = true,
// CHECK-LABEL: // Density: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos and smoothing_length.
// CHECK-NEXT: search(wash::backend::smoothingGeometry(run.support(), P.smoothing_length, P.id, backend.owned(), run.box(), 2, step, "Density", &Backend::combineMax, true), run.box(),
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); },
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); send(P.smoothing_length); });
// CHECK: ::Density(self, table.list(i));
// MPI-LABEL: // Density: force kernel, new neighbour search
// MPI-NEXT: // Neighbours read pos and smoothing_length.
// MPI-NEXT: search(wash::backend::smoothingGeometry({{.*}}"Density", &Backend::combineMax, true), run.box(),
// MPI-NEXT: [](auto send) { send(P.id); send(P.pos); },
// MPI-NEXT: [](auto send) { send(P.id); send(P.pos); send(P.smoothing_length); });
#include <wash/wash.hpp>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_density(double(ns.size()));
}

int main() {
  wash::set_smoothing_length_support(2.0, wash::Support::Symmetric);
  wash::set_max_iterations(1);
  wash::add_force_kernel(&Density);
  wash::start();
}
