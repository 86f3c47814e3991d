// The MPI driver follows the halo plan: a new search carries ids, positions
// and the first kernel's halo fields; a later kernel of the same search gets
// only the fields written since they were sent; own-only reads never travel.
// create_particle asks the backend for the id (and whether the row stays).
// RUN: rm -rf %t && %wash --backend=mpi -o %t %s 2>/dev/null
// RUN: grep -vE '^// [A-Z-]+:' %t/mpi-driver.mpi.cpp | FileCheck %s
// RUN: FileCheck %s --check-prefix=HEADER --input-file %t/mpi-driver.wash.hpp
// HEADER: #include <wash/mpi/backend.hpp>
// HEADER: using Backend = wash::mpi::Backend<2>;
// The id is the creation index the backend gives; it decides which rows stay.
// CHECK-LABEL: Self &create_particle(
// CHECK: const std::uint64_t id = backend.create(P, density, mass, smoothing_length, pos, vel);
// CHECK: P.id.push_back(id);
// CHECK: wash::backend::Run run(translated, backend.writes());
// CHECK: particles = backend.distribute(P, [&] { return run.radius(); });
// CHECK-LABEL: // Density: force kernel, new neighbour search
// CHECK-NEXT: // Neighbours read mass and pos.
// CHECK-NEXT: search(wash::backend::fixedGeometry(run.radius()), run.box(),
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); },
// CHECK-NEXT: [](auto send) { send(P.id); send(P.pos); send(P.mass); });
// CHECK: backend.forEachParticleChecked([](Index i) {
// CHECK-LABEL: // Pressure: force kernel, reuses the neighbour search of 'Density'
// CHECK-NEXT: // Neighbours read density, written since they were sent.
// CHECK-NEXT: backend.refresh([](auto send) { send(P.density); });
// CHECK-LABEL: // Heat: force kernel, reuses the neighbour search of 'Density'
// CHECK-NOT: refresh
// CHECK: run.endStep(step, frame);
// CHECK: backend.report(run);
#include <wash/wash.hpp>
#include <vector>

void Density(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double d = p.get_mass();
  for (const auto &n : ns)
    d += n.get_mass();
  p.set_density(d);
}

void Pressure(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = p.get_force_scalar("t");
  for (const auto &n : ns)
    s += n.get_density();
  p.set_force_scalar("pressure", s);
}

void Heat(wash::Particle &p, const std::vector<wash::Particle> &ns) {
  double s = 0;
  for (const auto &n : ns)
    s += n.get_mass() + n.get_density();
  p.set_force_scalar("t", s);
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_force("t", 1);
  wash::add_force_kernel(&Density);
  wash::add_force_kernel(&Pressure);
  wash::add_force_kernel(&Heat);
  wash::set_max_iterations(1);
  wash::start();
}
