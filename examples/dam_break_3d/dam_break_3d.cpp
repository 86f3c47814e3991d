// dam_break_3d: a column of water collapsing in a 3D box.
//
// Weakly compressible SPH (Mueller et al. 2003 kernels): density by summation
// with the poly6 kernel, a linear equation of state, pressure forces with the
// spiky kernel gradient, viscosity, gravity and damped walls. Shows a 3D
// scene, the acceleration property, a lambda inside a kernel and two force
// kernels sharing one neighbour search.
#include <wash/wash.hpp>

#include <cmath>
#include <vector>

constexpr double spacing = 0.025;
constexpr double h = 2.0 * spacing; // influence radius
constexpr wash::Vec3D boxSize{1.0, 0.6, 0.4};
constexpr wash::Vec3D columnSize{0.3, 0.5, 0.3};
constexpr double mass = 1000.0 * spacing * spacing * spacing;
constexpr double stiffness = 1000.0;
constexpr double viscosity = 0.5;
constexpr double gravity = -9.81;
constexpr double dt = 2.0e-4;
constexpr double wallDamping = 0.5;

double restDensity = 1000.0; // recomputed in Spawn for the lattice spacing

double Poly6(double r2) {
    if (r2 >= h * h) return 0.0;
    double d = h * h - r2;
    return 315.0 / (64.0 * PI * std::pow(h, 9)) * d * d * d;
}

double SpikyGradient(double r) { // magnitude, along the unit vector from j to i
    if (r >= h) return 0.0;
    return -45.0 / (PI * std::pow(h, 6)) * (h - r) * (h - r);
}

double ViscosityLaplacian(double r) {
    if (r >= h) return 0.0;
    return 45.0 / (PI * std::pow(h, 6)) * (h - r);
}

void Spawn() {
    // The density a particle of the lattice sees, so the column starts at rest.
    double lattice = 0.0;
    for (int i = -2; i <= 2; i++)
        for (int j = -2; j <= 2; j++)
            for (int k = -2; k <= 2; k++)
                lattice += mass * Poly6((i * i + j * j + k * k) * spacing * spacing);
    restDensity = lattice;

    int nx = int(columnSize.at(0) / spacing), ny = int(columnSize.at(1) / spacing),
        nz = int(columnSize.at(2) / spacing);
    for (int j = 0; j < ny; j++)
        for (int k = 0; k < nz; k++)
            for (int i = 0; i < nx; i++) {
                wash::Vec3D pos{(i + 0.5) * spacing, (j + 0.5) * spacing, (k + 0.5) * spacing};
                wash::create_particle(restDensity, mass, h, pos, wash::Vec3D{});
            }
}

void ComputeDensity(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    double density = p.get_mass() * Poly6(0.0);
    for (const auto& n : neighbours) {
        wash::Vec3D d = p.get_pos() - n.get_pos();
        density += n.get_mass() * Poly6(d.dot(d));
    }
    p.set_density(density);
    p.set_force_scalar("pressure", std::max(0.0, stiffness * (density - restDensity)));
}

void ComputeAcceleration(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const wash::Vec3D pos = p.get_pos();
    const double pressure = p.get_force_scalar("pressure");
    auto pairForce = [&](const wash::Particle& n) {
        wash::Vec3D d = pos - n.get_pos();
        double r = d.magnitude();
        if (r <= 0.0) return wash::Vec3D{};
        wash::Vec3D dir = d / r;
        double shared = (pressure + n.get_force_scalar("pressure")) / (2.0 * n.get_density());
        wash::Vec3D f = dir * (-n.get_mass() * shared * SpikyGradient(r));
        f += (n.get_vel() - p.get_vel()) * (viscosity * n.get_mass() / n.get_density() *
                                            ViscosityLaplacian(r));
        return f;
    };
    wash::Vec3D force{};
    for (const auto& n : neighbours)
        force += pairForce(n);
    p.set_acc(force / p.get_density() + wash::Vec3D{0.0, gravity, 0.0});
}

void Integrate(wash::Particle& p) {
    wash::Vec3D vel = p.get_vel() + p.get_acc() * dt;
    wash::Vec3D pos = p.get_pos() + vel * dt;
    for (int a = 0; a < 3; a++) {
        if (pos.at(a) < 0.0) {
            *pos[a] = -pos.at(a);
            *vel[a] = -vel.at(a) * wallDamping;
        } else if (pos.at(a) > boxSize.at(a)) {
            *pos[a] = 2.0 * boxSize.at(a) - pos.at(a);
            *vel[a] = -vel.at(a) * wallDamping;
        }
    }
    p.set_vel(vel);
    p.set_pos(pos);
}

int main(int argc, char** argv) {
    wash::set_precision("double");
    wash::set_influence_radius(h);
    wash::set_simulation_name("dam_break_3d");
    wash::add_force("pressure", 1);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&ComputeDensity);
    wash::add_force_kernel(&ComputeAcceleration);
    wash::add_update_kernel(&Integrate);
    wash::set_max_iterations(2000);
    wash::start();
    return 0;
}
