// channel_3d: flow between two walls, driven by a body force, periodic along
// the channel (x) and across it (z), closed by walls in y.
//
// A mixed box: set_bounding_box with periodic x and z; the y walls are physics
// in the Integrate kernel, as in the other examples. Uses a helper that takes
// the particle, a helper that takes the neighbour list, and the acceleration.
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

constexpr double spacing = 0.05;
constexpr double h = 1.2 * spacing;
constexpr double radius = 2.0 * h;
constexpr wash::Vec3D box{0.8, 0.5, 0.4};
constexpr double rho0 = 1000.0;
constexpr double c = 5.0;
constexpr double drive = 0.5; // body force along x
constexpr double mu = 0.05;
constexpr double dt = 0.2 * h / c;

double W(double r) {
    double q = r / h, sigma = 1.0 / (PI * h * h * h);
    if (q < 1.0) return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) return sigma * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return 0.0;
}

double dW(double r) {
    double q = r / h, sigma = 1.0 / (PI * h * h * h);
    if (q < 1.0) return sigma / h * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) return sigma / h * (-0.75 * (2.0 - q) * (2.0 - q));
    return 0.0;
}

void Spawn() {
    int nx = int(box.at(0) / spacing), ny = int(box.at(1) / spacing), nz = int(box.at(2) / spacing);
    double m = rho0 * spacing * spacing * spacing;
    for (int k = 0; k < nz; k++)
        for (int j = 0; j < ny; j++)
            for (int i = 0; i < nx; i++) {
                wash::Vec3D pos{(i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing};
                wash::create_particle(rho0, m, h, pos, wash::Vec3D{});
            }
}

double PressureOf(const wash::Particle& p) { return c * c * (p.get_density() - rho0); }

double DensityAround(const wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double rho = p.get_mass() * W(0.0);
    for (const auto& n : ns)
        rho += n.get_mass() * W((p.get_pos() - n.get_pos()).magnitude());
    return rho;
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    p.set_density(DensityAround(p, ns));
}

void Forces(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec3D acc{drive, 0.0, 0.0};
    for (const auto& n : ns) {
        wash::Vec3D d = p.get_pos() - n.get_pos();
        double r = d.magnitude();
        if (r <= 0.0) continue;
        double grad = dW(r);
        double pi = PressureOf(p), pj = PressureOf(n);
        double rhoi = p.get_density(), rhoj = n.get_density();
        acc -= d / r * (n.get_mass() * (pi / (rhoi * rhoi) + pj / (rhoj * rhoj)) * grad);
        acc += (p.get_vel() - n.get_vel()) * (n.get_mass() * 2.0 * mu / (rhoi * rhoj) * grad / r);
    }
    p.set_acc(acc);
}

void Integrate(wash::Particle& p) {
    wash::Vec3D vel = p.get_vel() + p.get_acc() * dt;
    wash::Vec3D pos = p.get_pos() + vel * dt;
    // Walls at y = 0 and y = box.y: reflect, no slip.
    if (pos.at(1) < 0.0 || pos.at(1) > box.at(1)) {
        *pos[1] = pos.at(1) < 0.0 ? -pos.at(1) : 2.0 * box.at(1) - pos.at(1);
        vel = wash::Vec3D{0.0, -0.5 * vel.at(1), 0.0};
    }
    p.set_vel(vel);
    p.set_pos(pos);
}

int main() {
    wash::set_precision("double");
    wash::set_influence_radius(radius);
    wash::set_bounding_box({0.0, 0.0, 0.0}, {box.at(0), box.at(1), box.at(2)}, {true, false, true});
    wash::set_simulation_name("channel_3d");
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Integrate);
    wash::set_max_iterations(500);
    wash::start();
}
