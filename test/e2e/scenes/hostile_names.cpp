// Output names with characters XML, CSV and HDF5 treat specially, for
// test/e2e/fault_escaped_names.sh (the reference only: the translator takes
// identifiers as force names):
//   hostile_names SIMULATION_NAME FORCE_NAME
// A scalar and a vector force of that name (the vector's with "_v" added).
#include <wash/wash.hpp>

#include <string>

std::string forceName;

void Spawn() {
  for (int i = 0; i < 20; ++i)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.05 * i, 0.5}, wash::Vec2D{0.0, 0.0});
}

void Count(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  p.set_force_scalar(forceName, double(neighbours.size()) + 0.25);
  p.set_force_vector(forceName + "_v", wash::Vec2D{double(p.get_id()), 0.5});
}

int main(int argc, char **argv) {
  if (argc < 3)
    return 2;
  forceName = argv[2];
  wash::set_influence_radius(0.12);
  wash::set_simulation_name(argv[1]);
  wash::add_force(forceName, 1);
  wash::add_force(forceName + "_v", 2);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Count);
  wash::set_max_iterations(2);
  wash::start();
}
