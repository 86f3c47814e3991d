// An init kernel that is not deterministic across MPI ranks: the last
// particle's position depends on the rank (Open MPI's environment), so the
// MPI program must stop with a message instead of running on mixed particles.
#include <wash/wash.hpp>

#include <cstdlib>

void Spawn() {
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  const double shift = rank ? 1e-3 * std::atoi(rank) : 0.0;
  for (int i = 0; i < 10; ++i)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i + (i == 9 ? shift : 0.0), 0.0},
                          wash::Vec2D{0.0, 0.0});
}

void Drift(wash::Particle& p) { p.set_pos(p.get_pos() + p.get_vel()); }

int main() {
  wash::set_influence_radius(0.15);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Drift);
  wash::set_max_iterations(2);
  wash::start();
}
