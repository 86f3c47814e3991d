// A 3D scene that uses one force name both as a scalar and as a vector: the
// reference runtime reports the second use at its source location.
#include <wash/wash.hpp>

#include <vector>

void Spawn() {
  for (int i = 0; i < 4; ++i)
    wash::create_particle(1.0, 1.0, 0.1, wash::Vec3D{0.05 * i, 0.0, 0.0}, wash::Vec3D{});
}

void Heat(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
  double sum = 0.0;
  for (const auto& n : neighbours)
    sum += n.get_density();
  p.set_force_scalar("heat", sum);
}

void Spread(wash::Particle& p) {
  // "heat" is a scalar, so reading it as a vector (line 21) is misuse
  p.set_vel(p.get_force_vector("heat"));
}

int main() {
  wash::set_influence_radius(0.1);
  wash::add_init_kernel(&Spawn);
  wash::add_force_kernel(&Heat);
  wash::add_update_kernel(&Spread);
  wash::set_max_iterations(1);
  wash::start();
}
