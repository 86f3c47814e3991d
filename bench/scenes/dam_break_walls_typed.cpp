// A 2D dam break in a tank of wall particles, written with particle types:
// walls are "wall" particles, the fluid kernels are registered for "fluid",
// and the walls' density (they are dummy particles whose pressure holds the
// fluid back) sums their fluid neighbours only, filtered as the neighbour list
// is built. dam_break_walls_flag.cpp is the same physics, the same arithmetic
// in the same order, with a "wall" force tested at the top of every kernel;
// bench/particle_types.sh runs the two side by side.
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
            w.set_type("wall");
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

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double rho = p.get_mass() * W(0.0);
    for (const wash::Particle& n : ns)
        rho += n.get_mass() * W((n.get_pos() - p.get_pos()).magnitude());
    p.set_density(rho);
}

void Rates(wash::Particle& p, const std::vector<wash::Particle>& ns) {
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
    p.set_vel(p.get_vel() + p.get_acc() * dt);
    p.set_pos(p.get_pos() + p.get_vel() * dt);
}

int main() {
    wash::add_particle_type("fluid");
    wash::add_particle_type("wall");
    wash::set_simulation_name("dam_break_walls_typed");
    wash::set_influence_radius(2.0 * h);
    wash::add_init_kernel(&Build);
    wash::add_force_kernel(&Density, "fluid");
    wash::add_force_kernel(&Density, "wall", "fluid");
    wash::add_force_kernel(&Rates, "fluid");
    wash::add_update_kernel(&Kick, "fluid");
    wash::set_max_iterations(200);
    wash::start();
}
