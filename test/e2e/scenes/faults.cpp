// A small scene for the runtime's fault tests (test/e2e/faults.sh,
// output_faults.sh, out_of_memory.sh): the first argument picks a kernel
// that fails on one particle, which no translation can see, by throwing an
// exception of the program's own: "update" or "force", or "int" (an update
// kernel throwing 42, no std::exception); anything else: none, the run
// completes. The second argument is the particle count (default
// 400; a huge one runs out of memory in create_particle), the third the
// simulation name.
#include <wash/wash.hpp>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

void Spawn() {
  const double count = wash::get_variable("count");
  for (double i = 0; i < count; ++i)
    wash::create_particle(1.0, 1.0, 0.1,
                          wash::Vec2D{0.01 * std::fmod(i, 20.0), 0.01 * std::floor(i / 20.0)},
                          wash::Vec2D{0.0, 0.0});
}

void Update(wash::Particle &p) {
  if (wash::get_variable("fail_in") == 1.0 && p.get_id() == 141)
    throw std::runtime_error("particle 141 refuses to move");
  if (wash::get_variable("fail_in") == 3.0 && p.get_id() == 141)
    throw 42;
  p.set_density(p.get_density() + 1.0);
}

void Force(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  if (wash::get_variable("fail_in") == 2.0 && p.get_id() == 233)
    throw std::runtime_error("particle 233 has " + std::to_string(neighbours.size()) +
                             " neighbours, too many");
  p.set_force_scalar("count", double(neighbours.size()));
}

int main(int argc, char **argv) {
  const std::string where = argc > 1 ? argv[1] : "";
  wash::set_influence_radius(0.015);
  wash::add_variable("fail_in", where == "update" ? 1.0 : where == "force" ? 2.0
                                          : where == "int"   ? 3.0
                                                             : 0.0);
  wash::add_variable("count", argc > 2 ? std::atof(argv[2]) : 400.0);
  if (argc > 3) // where output goes: test/e2e/output_faults.sh
    wash::set_simulation_name(argv[3]);
  wash::add_force("count", 1);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Update);
  wash::add_force_kernel(&Force);
  wash::set_max_iterations(3);
  wash::start();
}
