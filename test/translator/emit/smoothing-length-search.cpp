// Under the smoothing-length rule a search takes its geometry from the
// smoothing lengths (and, with MPI, the largest over all ranks) and keeps
// every particle's list, found within its own support radius, for the kernels
// of that search.
// RUN: rm -rf %t && %wash --backend=openmp -o %t/omp %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/omp/smoothing-length-search.openmp.cpp | FileCheck %s
// RUN: %wash --backend=mpi -o %t/mpi %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/mpi/smoothing-length-search.mpi.cpp | FileCheck %s --check-prefix=MPI
// CHECK: wash::backend::NeighbourTable<3, Stored> table;
// The backend's search reads the smoothing lengths (an MPI halo reaches only
// as far as each particle's pairs).
// CHECK: backend.search(P, at, box, wash::backend::HaloColumns<Kept, Fresh>{kept, fresh}, [](std::uint32_t row) { return double(P.smoothing_length[row]); });
// CHECK: table.build(backend.grid(), P.pos, P.id, P.smoothing_length, at, backend.owned());
// CHECK: .floatStorage = false, .smoothingLengthSearch = true,
// CHECK-LABEL: // Density: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos.
// CHECK-NEXT: search(wash::backend::smoothingGeometry(run.support(), P.smoothing_length, P.id, backend.owned(), run.box(), 3, step, "Density", &Backend::combineMax), run.box(),
// CHECK: ::Density(self, table.list(i));
// CHECK-LABEL: // Adapt: update kernel
// CHECK-LABEL: // Force: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read pos.
// CHECK-NEXT: search(wash::backend::smoothingGeometry(
// The domain's cells: the largest support radius at the start (MPI calls it).
// MPI: backend.distribute(P, [&] {
// MPI-NEXT: return wash::backend::smoothingGeometry(run.support(), P.smoothing_length, P.id, backend.owned(), run.box(), 3, 0, "(start)").domainCellSize();
// MPI-LABEL: // Density: force kernel, new neighbour search
// MPI-NEXT: // Neighbours read pos.
// MPI-NEXT: search(wash::backend::smoothingGeometry(run.support(), P.smoothing_length, P.id, backend.owned(), run.box(), 3, step, "Density", &Backend::combineMax), run.box(),
#include <wash/wash.hpp>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  p.set_density(double(ns.size()));
}
void Adapt(wash::Particle &p) { p.set_smoothing_length(p.get_smoothing_length() * 1.01); }
void Force(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  wash::Vec3D towards = ns.empty() ? p.get_pos() : ns[0].get_pos();
  p.set_acc(towards);
}

int main() {
  wash::set_smoothing_length_support(2.0);
  wash::set_max_iterations(1);
  wash::add_force_kernel(&Density);
  wash::add_update_kernel(&Adapt);
  wash::add_force_kernel(&Force);
  wash::start();
}
