// taylor_green: the decaying Taylor-Green vortex in a periodic 2D box.
//
// Weakly compressible SPH (cubic spline kernel, summation density, linear
// equation of state, Monaghan's artificial-viscosity-free pressure force plus
// a Morris-style physical viscosity) in a box periodic on both axes: particles
// leave through one face and come back through the other, and neighbours are
// found across the faces. The vortex's kinetic energy decays as
// exp(-16 pi^2 nu t) for a unit box.
#include <wash/wash.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

constexpr double rho0 = 1.0;
constexpr double soundSpeed = 10.0;
constexpr double nu = 0.01;

// SIDE particles along a unit of length (main's first argument, 40).
double spacing() { return 1.0 / wash::get_variable("side"); }
double smoothingLength() { return 1.3 * spacing(); }

// The cubic spline (support 2h) and the linear equation of state of wash/sph.
double W(double r) { return wash::sph::cubic_spline::W<2>(r, smoothingLength()); }
double dW(double r) { return wash::sph::cubic_spline::dWdr<2>(r, smoothingLength()); } // dW/dr
constexpr wash::sph::LinearEos eos{rho0, soundSpeed};

// A row of UNITS unit squares (main's second argument, 1): the vortex has
// period 1, so each holds the same flow.
void Spawn() {
    const int side = int(wash::get_variable("side"));
    const int units = int(wash::get_variable("units"));
    const double dx = spacing();
    for (int j = 0; j < side; j++)
        for (int i = 0; i < units * side; i++) {
            double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
            wash::Vec2D vel{std::sin(2 * PI * x) * std::cos(2 * PI * y),
                            -std::cos(2 * PI * x) * std::sin(2 * PI * y)};
            wash::create_particle(rho0, rho0 * dx * dx, smoothingLength(), wash::Vec2D{x, y}, vel);
        }
}

void Density(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    double rho = p.get_mass() * W(0.0);
    for (const auto& n : ns)
        rho += n.get_mass() * W((p.get_pos() - n.get_pos()).magnitude());
    p.set_density(rho);
    p.set_force_scalar("pressure", eos.pressure(rho));
}

void Forces(wash::Particle& p, const std::vector<wash::Particle>& ns) {
    wash::Vec2D acc{};
    const double pi = p.get_force_scalar("pressure"), rhoi = p.get_density();
    for (const auto& n : ns) {
        wash::Vec2D d = p.get_pos() - n.get_pos();
        double r = d.magnitude();
        if (r <= 0.0) continue;
        double rhoj = n.get_density(), grad = dW(r);
        double pressureTerm = pi / (rhoi * rhoi) + n.get_force_scalar("pressure") / (rhoj * rhoj);
        acc -= d / r * (n.get_mass() * pressureTerm * grad);
        // Morris et al. (1997) viscosity
        acc += (p.get_vel() - n.get_vel()) * (n.get_mass() * 2.0 * nu / rhoj * grad / r);
    }
    p.set_acc(acc);
}

void Move(wash::Particle& p) {
    const double dt = 0.1 * smoothingLength() / soundSpeed;
    p.set_vel(p.get_vel() + p.get_acc() * dt);
    p.set_pos(p.get_pos() + p.get_vel() * dt);
    wash::Vec2D v = p.get_vel();
    p.set_force_scalar("kinetic_energy", 0.5 * p.get_mass() * v.dot(v));
}

// taylor_green [SIDE [UNITS]]: a row of UNITS periodic unit squares is the
// weak-scaling scene of bench/mpi_weak_scaling.sh (one square a rank, each
// with the same neighbours at any rank count).
int main(int argc, char** argv) {
    const int side = argc > 1 ? std::max(8, std::atoi(argv[1])) : 40;
    const int units = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
    wash::set_precision("double");
    wash::set_influence_radius(2.0 * (1.3 * (1.0 / side))); // the spline's support, 2h
    wash::set_bounding_box({0.0, 0.0}, {double(units), 1.0}, {true, true});
    wash::set_simulation_name("taylor_green");
    wash::add_variable("side", side);
    wash::add_variable("units", units);
    wash::add_force("pressure", 1);
    wash::add_force("kinetic_energy", 1);
    wash::add_init_kernel(&Spawn);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Move);
    wash::set_max_iterations(1000);
    wash::start();
}
