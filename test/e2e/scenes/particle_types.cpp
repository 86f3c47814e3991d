// Particle types: fluid falls into a box of wall particles. Fluid kernels are
// registered for "fluid"; the walls' density comes from their fluid
// neighbours only (a neighbour-type filter); the force on the fluid sums
// over neighbours of every type and asks is_type of each; fluid that falls
// below the floor's top becomes a "sediment" particle (set_type in an update
// kernel) that no kernel moves any more; the time step is a Min reduction
// over the fluid alone.
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

constexpr double spacing = 0.05;
constexpr double radius = 2.5 * spacing;
constexpr double floorTop = 0.0;
constexpr const char* Wall = "wall"; // a type name the translator evaluates

void Build() {
    for (int i = -3; i < 33; ++i)     // the floor, three rows
        for (int j = -3; j < 0; ++j) {
            wash::Particle& p = wash::create_particle(1.0, 1.0, spacing,
                                                      wash::Vec2D{i * spacing, j * spacing},
                                                      wash::Vec2D{});
            p.set_type("wall");
        }
    for (int j = 0; j < 16; ++j)      // the side walls
        for (int k = 0; k < 3; ++k) {
            auto& l = wash::create_particle(1.0, 1.0, spacing,
                                            wash::Vec2D{(-3 + k) * spacing, j * spacing},
                                            wash::Vec2D{});
            l.set_type("wall");
            auto& r = wash::create_particle(1.0, 1.0, spacing,
                                            wash::Vec2D{(30 + k) * spacing, j * spacing},
                                            wash::Vec2D{});
            r.set_type("wall");
        }
    for (int i = 0; i < 14; ++i)      // a block of fluid, created as the default type
        for (int j = 0; j < 12; ++j)
            wash::create_particle(1.0, 1.0, spacing,
                                  wash::Vec2D{(1 + i) * spacing + 0.003 * j, (2 + j) * spacing},
                                  wash::Vec2D{0.1 * (j % 3), 0.0});
}

double Weight(double r) {
    const double q = 1.0 - r / radius;
    return q > 0.0 ? q * q : 0.0;
}

void FluidDensity(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double rho = 1.0;
    for (const wash::Particle& n : ns)
        rho += Weight((n.get_pos() - p.get_pos()).magnitude()) * (n.is_type("wall") ? 1.5 : 1.0);
    p.set_density(rho);
}

void WallDensity(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double rho = 1.0;
    for (const wash::Particle& n : ns) // fluid neighbours only
        rho += Weight((n.get_pos() - p.get_pos()).magnitude());
    p.set_density(rho);
}

void Pressure(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec2D force{0.0, -9.81};
    const double pi = p.get_density() - 1.0;
    for (const wash::Particle& n : ns) {
        const wash::Vec2D d = p.get_pos() - n.get_pos();
        const double r = d.magnitude();
        if (r <= 0.0)
            continue;
        const double pn = n.get_density() - 1.0;
        const double stiff = n.is_type("fluid") ? 2.0 : 4.0;
        force += d * (stiff * (pi + pn) * Weight(r) / r);
    }
    p.set_acc(force);
}

double Speed(const wash::Particle& p) {
    const double v = p.get_vel().magnitude() + 1.0;
    return 0.2 * spacing / v;
}

void Kick(wash::Particle& p) {
    const double dt = std::min(wash::get_time_step(), 0.004);
    p.set_vel((p.get_vel() + p.get_acc() * dt) * 0.999);
    p.set_pos(p.get_pos() + p.get_vel() * dt);
    if (p.get_pos().at(1) < floorTop - 0.5 * spacing)
        p.set_type("sediment");
}

void Count(wash::Particle& p) { p.set_force_scalar("age", p.get_force_scalar("age") + 1.0); }

int main() {
    wash::add_particle_type("fluid");
    wash::add_particle_type(Wall);
    wash::add_particle_type("sediment");
    wash::set_simulation_name("particle_types");
    wash::set_influence_radius(radius);
    wash::add_force("age", 1);
    wash::add_init_kernel(&Build);
    wash::add_force_kernel(&FluidDensity, "fluid");
    wash::add_force_kernel(&WallDensity, Wall, "fluid");
    wash::add_force_kernel(&Pressure, "fluid");
    wash::add_reduction_kernel(&Speed, wash::Reduction::Min, "time_step", "fluid");
    wash::add_update_kernel(&Kick, "fluid");
    wash::add_update_kernel(&Count, "sediment");
    wash::set_max_iterations(100);
    wash::start();
}
