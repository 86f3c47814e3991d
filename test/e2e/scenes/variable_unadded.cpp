// A kernel reads a variable that main adds only when asked ("add" as the
// first argument; otherwise it adds another): the translator cannot know
// which, and without it the run must stop at the read, with the reference's
// message and location, while with it a void kernel's writes must reach the
// kernels' reads (test/e2e/variable_slots.sh).
#include <wash/wash.hpp>

#include <string>

void Spawn() {
  for (int i = 0; i < 100; i++)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.05 * (i % 10), 0.05 * (i / 10)},
                          wash::Vec2D{1.0, 0.5});
}

void Grow() { wash::set_variable("gain", wash::get_variable("gain") * 1.5 + 0.25); }

void Move(wash::Particle &p) {
  p.set_pos(p.get_pos() + p.get_vel() * (0.01 * wash::get_variable("gain")));
}

int main(int argc, char **argv) {
  wash::set_influence_radius(0.1);
  // A name known only at run time: the translator cannot tell which.
  const std::string name = argc > 1 && std::string(argv[1]) == "add" ? "gain" : "other";
  wash::add_variable(name, 1.0);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Move);
  wash::add_void_kernel(&Grow);
  wash::set_max_iterations(5);
  wash::start();
}
