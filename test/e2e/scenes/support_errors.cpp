// Misuse of the smoothing-length rule, chosen by the first argument: "both"
// neighbour rules, "none", or "grow" (h doubles every step until the support
// radius is more than half the periodic box: the run must stop there).
#include <wash/wash.hpp>

#include <string>
#include <vector>

void Spawn() {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      wash::create_particle(1.0, 1.0, 0.02, wash::Vec2D{0.25 * i, 0.25 * j}, wash::Vec2D{});
}

void Count(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  p.set_density(double(neighbours.size()));
}

void Grow(wash::Particle &p) { p.set_smoothing_length(2.0 * p.get_smoothing_length()); }

int main(int argc, char **argv) {
  const std::string mode = argc > 1 ? argv[1] : "grow";
  if (mode != "none")
    wash::set_smoothing_length_support(2.0);
  if (mode == "both")
    wash::set_influence_radius(0.1);
  wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, true});
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Count);
  wash::add_update_kernel(&Grow);
  wash::set_max_iterations(20);
  wash::start();
}
