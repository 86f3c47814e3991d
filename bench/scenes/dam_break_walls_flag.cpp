// A 2D dam break in a tank of wall particles, written with a "wall" flag (a
// scalar force, 1 for walls) that every kernel tests first, as one writes it
// without particle types. dam_break_walls_typed.cpp is the same physics, the
// same arithmetic in the same order, with types; bench/particle_types.sh runs
// the two side by side.
#include <wash/wash.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

constexpr double dx = 0.01;               // particle spacing
constexpr double h = 1.3 * dx;            // smoothing length
constexpr double rho0 = 1000.0, c0 = 30.0, g = 9.81, dt = 1e-4, alpha = 0.1;
constexpr int columnsFluid = 60, rowsFluid = 120, tankColumns = 200, tankRows = 140, layers = 3;

void Build() {
    const double m = rho0 * dx * dx;
    for (int i = -layers; i < tankColumns + layers; ++i)
        for (int j = -layers; j < tankRows; ++j) {
            const bool inside = i >= 0 && i < tankColumns && j >= 0;
            if (inside)
                continue;
            wash::Particle& w = wash::create_particle(rho0, m, h,
                                                      wash::Vec2D{(i + 0.5) * dx, (j + 0.5) * dx},
                                                      wash::Vec2D{});
            w.set_force_scalar("wall", 1.0);
        }
    for (int i = 0; i < columnsFluid; ++i)
        for (int j = 0; j < rowsFluid; ++j)
            wash::create_particle(rho0, m, h, wash::Vec2D{(i + 0.5) * dx, (j + 0.5) * dx},
                                  wash::Vec2D{});
}

double W(double r) { // cubic spline, 2D, support 2h
    const double q = r / h, sigma = 10.0 / (7.0 * PI * h * h);
    if (q >= 2.0)
        return 0.0;
    if (q >= 1.0)
        return sigma * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
}

double dW(double r) { // dW/dr
    const double q = r / h, sigma = 10.0 / (7.0 * PI * h * h);
    if (q >= 2.0)
        return 0.0;
    if (q >= 1.0)
        return -sigma * 0.75 * (2.0 - q) * (2.0 - q) / h;
    return sigma * (-3.0 * q + 2.25 * q * q) / h;
}

// A linear equation of state without tension: p = max(0, c0^2 (rho - rho0)).
double Pressure(double rho) { return std::max(0.0, c0 * c0 * (rho - rho0)); }

bool IsWall(const wash::Particle& p) { return p.get_force_scalar("wall") > 0.5; }

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    if (IsWall(p))
        return;
    double rho = p.get_mass() * W(0.0);
    for (const wash::Particle& n : ns)
        rho += n.get_mass() * W((n.get_pos() - p.get_pos()).magnitude());
    p.set_density(rho);
}

void WallDensity(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    if (!IsWall(p))
        return;
    double rho = p.get_mass() * W(0.0);
    for (const wash::Particle& n : ns)
        if (!IsWall(n))
            rho += n.get_mass() * W((n.get_pos() - p.get_pos()).magnitude());
    p.set_density(rho);
}

void Rates(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    if (IsWall(p))
        return;
    const double rhoi = p.get_density(), pi = Pressure(rhoi);
    wash::Vec2D a{0.0, -g};
    for (const wash::Particle& n : ns) {
        const wash::Vec2D d = p.get_pos() - n.get_pos();
        const double r = d.magnitude();
        if (r <= 0.0)
            continue;
        const double rhoj = n.get_density(), pj = Pressure(rhoj);
        double term = pi / (rhoi * rhoi) + pj / (rhoj * rhoj);
        const double vr = (p.get_vel() - n.get_vel()).dot(d);
        if (vr < 0.0) { // artificial viscosity
            const double mu = h * vr / (r * r + 0.01 * h * h);
            term += -alpha * c0 * mu / (0.5 * (rhoi + rhoj));
        }
        a -= d * (n.get_mass() * term * dW(r) / r);
    }
    p.set_acc(a);
}

void Kick(wash::Particle& p) {
    if (IsWall(p))
        return;
    p.set_vel(p.get_vel() + p.get_acc() * dt);
    p.set_pos(p.get_pos() + p.get_vel() * dt);
}

int main() {
    wash::set_simulation_name("dam_break_walls_flag");
    wash::add_force("wall", 1);
    wash::set_influence_radius(2.0 * h);
    wash::add_init_kernel(&Build);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&WallDensity);
    wash::add_force_kernel(&Rates);
    wash::add_update_kernel(&Kick);
    wash::set_max_iterations(200);
    wash::start();
}
