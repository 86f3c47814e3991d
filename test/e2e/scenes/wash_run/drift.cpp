// wash run's scene: a small lattice drifting at a speed from a header of its
// own, spread by a pair force. A few steps, so that it runs at once.
#include <wash/wash.hpp>

#include "drift.hpp"

#include <vector>

constexpr int side = 8;
constexpr double spacing = 1.0 / side;

void Spawn() {
    for (int k = 0; k < side * side; k++)
        wash::create_particle(1.0, 1.0, spacing,
                              wash::Vec2D{(k % side + 0.5) * spacing, (k / side + 0.5) * spacing},
                              wash::Vec2D{DriftSpeed, 0.0});
}

void Spread(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double density = 1.0;
    for (const auto& n : ns)
        density += 1.0 - (p.get_pos() - n.get_pos()).magnitude() / (2.0 * spacing);
    p.set_density(density);
}

void Move(wash::Particle& p) {
    p.set_vel(p.get_vel() * (1.0 / p.get_density() + 0.5));
    p.set_pos(p.get_pos() + p.get_vel() * 0.01);
}

int main() {
    wash::set_influence_radius(2.0 * spacing);
    wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, true});
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Spread);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(10);
    wash::start();
}
