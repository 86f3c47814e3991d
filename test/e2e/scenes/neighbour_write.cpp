// Writes to a neighbour, which the translator rejects (NeighbourWrite): the
// reference build must stop at the write with the same message. Only ever
// built against the reference runtime. The first argument picks the write:
// "cast" (const_cast) or "copy" (through a copy of the handle); anything
// else writes nothing and the run completes.
#include <wash/wash.hpp>

#include <string>

static std::string how;

void Spawn() {
  for (int i = 0; i < 4; ++i)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{0.0, 0.0});
}

void Touch(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  for (const wash::Particle &n : neighbours) {
    if (how == "cast")
      const_cast<wash::Particle &>(n).set_density(p.get_density());
    wash::Particle copy = n;
    if (how == "copy")
      copy.set_force_scalar("heat", 1.0);
  }
  p.set_force_scalar("heat", 0.5);
}

int main(int argc, char **argv) {
  how = argc > 1 ? argv[1] : "";
  wash::set_influence_radius(0.15);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Touch);
  wash::set_max_iterations(2);
  wash::start();
}
