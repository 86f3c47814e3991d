// heat_diffusion: heat spreading through a slowly stirred 2D plate, in float.
//
// SPH heat conduction (Brookshaw's Laplacian) on particles that a rotating
// flow keeps moving, so the neighbour search is redone every step. Shows
// float storage, helpers that take the neighbour list and index it
// (`neighbours[k]`, `neighbours.size()`), a helper taking `const
// wash::Particle&` that is called with the particle itself and with its
// neighbours, and a property (temperature) written by a force kernel on its
// particle while it reads it through neighbours: a snapshot hazard.
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

constexpr int side = 48;
constexpr double spacing = 1.0 / side;
constexpr double radius = 2.5 * spacing;
constexpr double conductivity = 2.0e-3;
constexpr double spin = 0.5; // rad/s
constexpr double dt = 0.01;

double KernelGradient(double r) { // d/dr of the 2D cubic spline, support 'radius'
    double q = 2.0 * r / radius;
    double sigma = 10.0 / (7.0 * PI * (radius / 2.0) * (radius / 2.0));
    double dq = 2.0 / radius;
    if (q < 1.0) return sigma * dq * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) return sigma * dq * (-0.75 * (2.0 - q) * (2.0 - q));
    return 0.0;
}

double KernelValue(double r) {
    double q = 2.0 * r / radius;
    double sigma = 10.0 / (7.0 * PI * (radius / 2.0) * (radius / 2.0));
    if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) return sigma * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return 0.0;
}

double temperatureOf(const wash::Particle& p) { return p.get_force_scalar("temperature"); }

void Spawn() {
    for (int y = 0; y < side; y++)
        for (int x = 0; x < side; x++) {
            // A deterministic jitter so that the lattice is not perfect.
            double jx = 0.1 * spacing * std::sin(12.9898 * x + 78.233 * y);
            double jy = 0.1 * spacing * std::cos(39.3468 * x + 11.135 * y);
            wash::Vec2D pos{(x + 0.5) * spacing - 0.5 + jx, (y + 0.5) * spacing - 0.5 + jy};
            auto& p = wash::create_particle(1.0, spacing * spacing, radius, pos, wash::Vec2D{});
            double r = (pos - wash::Vec2D{0.15, 0.1}).magnitude();
            p.set_force_scalar("temperature", r < 0.15 ? 1.0 : 0.0);
        }
}

// Density by summation, through a helper that indexes the neighbour list.
double DensitySum(const wash::Particle& self, const std::vector<wash::Particle>& ns) {
    double sum = self.get_mass() * KernelValue(0.0);
    for (size_t k = 0; k < ns.size(); k++) {
        const wash::Particle& n = ns[k];
        sum += n.get_mass() * KernelValue((n.get_pos() - self.get_pos()).magnitude());
    }
    return sum;
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    p.set_density(DensitySum(p, neighbours));
}

void Conduct(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    double laplacian = 0.0;
    for (size_t k = 0; k < neighbours.size(); k++) {
        wash::Vec2D d = p.get_pos() - neighbours[k].get_pos();
        double r = d.magnitude();
        if (r <= 0.0) continue;
        double weight = 2.0 * neighbours[k].get_mass() / neighbours[k].get_density();
        laplacian += weight * (temperatureOf(p) - temperatureOf(neighbours[k])) * KernelGradient(r) / r;
    }
    // Written here while neighbours read it: they must see the value from the
    // start of the kernel.
    p.set_force_scalar("temperature", temperatureOf(p) + dt * conductivity * laplacian);
    p.set_force_scalar("heat_flow", laplacian);
}

void Stir(wash::Particle& p) {
    wash::Vec2D pos = p.get_pos();
    double swirl = p.get_id() % 2 == 0 ? spin : 0.9 * spin;
    wash::Vec2D vel{-swirl * pos.at(1), swirl * pos.at(0)};
    p.set_vel(vel);
    p.set_pos(pos + vel * dt);
}

int main() {
    wash::set_precision("float");
    wash::set_influence_radius(radius);
    wash::set_simulation_name("heat_diffusion");
    wash::add_force("temperature", 1);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Conduct);
    wash::add_update_kernel(&Stir);
    wash::set_max_iterations(500);
    wash::start();
}
