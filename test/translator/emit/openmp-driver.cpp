// The OpenMP program runs every per-particle kernel through the OpenMP loop
// without synchronisation: each iteration writes only its own particle.
// RUN: rm -rf %t && %wash --backend=openmp -o %t %s 2>/dev/null
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/openmp-driver.wash.hpp
// RUN: grep -vE '^// [A-Z-]+:' %t/openmp-driver.openmp.cpp | FileCheck %s --implicit-check-not='{{atom}}ic' --implicit-check-not='{{crit}}ical'
// RUN: FileCheck %s --check-prefix=CMAKE --input-file %t/CMakeLists.txt
// HEADER: #include <wash/openmp/backend.hpp>
// HEADER: using Backend = wash::openmp::Backend<2>;
// CHECK: const wash::backend::Translation translated{.backend = Backend::name, .dimensions = 2,
// CHECK-NEXT: .floatStorage = false, .smoothingLengthSearch = false,
// CHECK-NEXT: .program = "kernels: force Count; update Drift; columns:
// CHECK-NEXT: wash::backend::Run run(translated, backend.writes());
// CHECK: backend.forEachParticleChecked([](Index i) {
// CHECK: ::Count(self, NeighbourList(backend.grid(), P.pos, i));
// CHECK: backend.forEachParticleChecked([](Index i) {
// CHECK: ::Drift(self);
// CMAKE: find_package(wash REQUIRED CONFIG HINTS
// CMAKE: add_executable(openmp-driver-openmp openmp-driver.openmp.cpp)
// CMAKE: target_link_libraries(openmp-driver-openmp PRIVATE wash::openmp)
#include <wash/wash.hpp>
#include <vector>

void Count(wash::Particle& p, const std::vector<wash::Particle>& ns) {
  p.set_density(double(ns.size()));
}
void Drift(wash::Particle& p) { p.set_pos(p.get_pos() + wash::Vec2D{0.01, 0.0}); }

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force_kernel(&Count);
  wash::add_update_kernel(&Drift);
  wash::set_max_iterations(1);
  wash::start();
}
