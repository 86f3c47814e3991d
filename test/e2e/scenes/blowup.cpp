// A scene that goes bad on purpose: velocities grow a hundredfold per step
// until they overflow, so the run must stop with a message at step 2.
#include <wash/wash.hpp>

void Spawn() {
  for (int i = 0; i < 10; ++i)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D{0.1 * i, 0.0}, wash::Vec2D{1e120, 0.0});
}

void Accelerate(wash::Particle& p) { p.set_vel(p.get_vel() * 1e100); }

int main() {
  wash::set_influence_radius(0.15);
  wash::add_init_kernel(&Spawn);
  wash::add_update_kernel(&Accelerate);
  wash::set_max_iterations(10);
  wash::start();
}
