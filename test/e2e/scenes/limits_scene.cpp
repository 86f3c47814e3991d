// A 2D scene for the run's limits (test/e2e/fault_hangs.sh,
// fault_mpi_limits.sh): no iteration count and no time step, and, by its
// first argument, one particle out of place.
//
//   limits_scene [nan|far|far-open|tiny]
// nan: particle 9 is created at x = NaN; far: particle 3 is created 10^7 box
// lengths to the right of the periodic box (it wraps in); far-open: the same
// in a box that is not periodic; tiny: an influence radius of 1e-9.
#include <wash/wash.hpp>

#include <cmath>
#include <cstring>

void Spawn() {
  const double mode = wash::get_variable("mode");
  for (int i = 0; i < 16; ++i) {
    double x = 0.125 + 0.25 * (i % 4);
    const double y = 0.125 + 0.25 * (i / 4);
    if (mode == 1.0 && i == 9)
      x = NAN;
    if ((mode == 2.0 || mode == 3.0) && i == 3)
      x += 1e7;
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D(x, y), wash::Vec2D(0.1, 0.05 * (i % 3)));
  }
}

void Push(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  wash::Vec2D acc(0.0, 0.0);
  for (const wash::Particle &q : neighbours)
    acc += (p.get_pos() - q.get_pos()) * 0.01;
  p.set_acc(acc);
}

void Move(wash::Particle &p) {
  p.set_vel(p.get_vel() + p.get_acc() * 0.01);
  p.set_pos(p.get_pos() + p.get_vel() * 0.01);
}

int main(int argc, char **argv) {
  const char *mode = argc > 1 ? argv[1] : "";
  const bool open = std::strcmp(mode, "far-open") == 0;
  wash::add_variable("mode", std::strcmp(mode, "nan") == 0   ? 1.0
                             : std::strcmp(mode, "far") == 0 ? 2.0
                             : open                          ? 3.0
                                                             : 0.0);
  wash::set_influence_radius(std::strcmp(mode, "tiny") == 0 ? 1e-9 : 0.3);
  wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {!open, !open});
  wash::set_simulation_name("limits_scene");
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Push);
  wash::add_update_kernel(&Move);
  wash::start();
}
