// Float storage read back right after it is written: an update kernel sets
// the velocity, then reads it to move the particle. The position must be
// computed from the stored (float) velocity, as in the reference. g++ 12's
// tree SLP vectoriser uses the unrounded double instead (positions 1 ULP
// off) unless the store goes through wash::backend::rounded
// (docs/performance.md, "g++ and float storage").
#include <wash/wash.hpp>

#include <vector>

constexpr double dt = 0.01;

void Spawn() {
    for (int j = 0; j < 16; j++)
        for (int i = 0; i < 16; i++)
            wash::create_particle(1.0, 1.0, 0.05, wash::Vec2D{0.05 * i + 0.003 * j, 0.05 * j},
                                  wash::Vec2D{0.1 * (i % 3), -0.07 * (j % 5)});
}

void Pull(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec2D a{0.0, -9.81};
    for (const auto& n : ns)
        a += (n.get_pos() - p.get_pos()) * 3.0;
    p.set_force_vector("a", a);
}

void Move(wash::Particle& p) {
    p.set_vel(p.get_vel() + p.get_force_vector("a") * dt);
    p.set_pos(p.get_pos() + p.get_vel() * dt);
}

int main() {
    wash::set_precision("float");
    wash::set_influence_radius(0.08);
    wash::add_force("a", 2);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Pull);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(50);
    wash::start();
}
