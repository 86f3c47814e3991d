// A scene in several files, as a user shares code between scenes: the wall
// helpers live in a header in a subfolder (which includes <wash/wash.hpp>
// and a header of its own one level deeper), the pair force in a header found
// on an include path (-I include). Fluid particles fall onto a floor of fixed
// wall particles and are pushed apart by a pair force.
#include <wash/wash.hpp>

#include "scene/walls.hpp"
#include <forces/pair.hpp>
// Included twice, through pair.hpp too: its #pragma once must hold.
#include "scene/walls.hpp"

#include <cmath>
#include <vector>

void Spawn() {
    for (int i = 0; i < 40; i++) // the floor: fixed wall particles
        wash::create_particle(1.0, WallMass, H, wash::Vec2D{0.025 * i, 0.02},
                              wash::Vec2D{0.0, 0.0});
    for (int j = 0; j < 12; j++)
        for (int i = 0; i < 16; i++)
            wash::create_particle(1.0, 1.0, H,
                                  wash::Vec2D{0.2 + 0.035 * i + 0.004 * std::sin(3.0 * j),
                                              0.1 + 0.035 * j},
                                  wash::Vec2D{0.1 * std::cos(0.7 * i + j), 0.0});
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    p.set_density(1.0 + DensitySum(p, ns));
}

void Forces(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec2D f{0.0, 0.0};
    for (const auto& n : ns)
        f += PairForce(p, n);
    p.set_force_vector("push", f);
}

void Move(wash::Particle& p) {
    if (IsWall(p))
        return;
    wash::Vec2D vel = p.get_vel() + (p.get_force_vector("push") + wash::Vec2D{0.0, -1.0}) * 0.002;
    p.set_vel(vel);
    p.set_pos(p.get_pos() + vel * 0.002);
    KeepAboveFloor(p);
}

int main() {
    wash::set_influence_radius(H);
    wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, false});
    wash::add_force("push", 2);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(200);
    wash::start();
}
