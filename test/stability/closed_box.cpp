// closed_box: a closed system for the stability tests. Nothing enters or
// leaves it, so its total energy and momentum must stay what they were.
//
// A 2D ideal gas (gamma = 5/3) in the unit box, periodic on both axes: no
// walls, no external force. Compressible SPH with a fixed smoothing length
// (cubic spline, support 2h), summation density, the symmetric pressure force
// and the internal energy equation, with Monaghan (1992) artificial viscosity,
// which turns kinetic energy into heat in the shocks the initial flow steepens
// into. In that form total energy E = sum m (v^2/2 + u) and total momentum
// P = sum m v are conserved exactly by the equations in continuous time; only
// the time integration (kick-drift-kick leapfrog, constant dt) and rounding
// change them. The force between two particles is the same expression
// evaluated from either side with the sign of the separation flipped, so the
// pair's momentum exchange cancels exactly up to rounding.
//
// The initial flow: a uniform drift (0.1, 0.05), so that the momentum to keep
// is not zero and particles cross the periodic faces; a shear sin(2 pi y) in x
// and sin(2 pi x) in y; and a compressive sin(2 pi x) in x, at Mach up to
// about 0.8, which steepens into weak shocks within about half a time unit.
//
// Every step (iteration) ends with one line on stdout,
//   step=S time=T energy=E kinetic=K momentum_x=PX momentum_y=PY
// for the state at the end of the runtime's step S (numbered as in its error
// messages), from Sum reductions, which are exact and rounded once, so every
// backend prints the same bits (%.17g). Step 1 only evaluates the forces of the
// initial state (dt = 0), so its line is the initial state, time 0: a run of
// N steps advances N - 1 time steps, to time (N - 1) dt.
//
//   closed_box [dt_factor]   multiply the time step by dt_factor (default 1);
//                            a large factor makes the run blow up on purpose.
#include <wash/wash.hpp>
#include <wash/sph/diagnostics.hpp>
#include <wash/sph/dissipation.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/leapfrog.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace sph = wash::sph;

constexpr int side = 32; // side x side particles
constexpr double spacing = 1.0 / side;
constexpr double h = 1.3 * spacing;
constexpr double radius = 2.0 * h; // support of the cubic spline
constexpr double adiabaticIndex = 5.0 / 3.0;
constexpr double rho0 = 1.0;
constexpr double energy0 = 0.9; // specific internal energy: sound speed 1
constexpr double driftX = 0.1;
constexpr double driftY = 0.05;
constexpr double shear = 0.3;
constexpr double compression = 0.3;
constexpr double alphaAV = 1.0;
constexpr double betaAV = 2.0;
// Courant 0.25 against the fastest signal at the start (sound speed 1, flow
// speed at most about 0.8, so 2 leaves room for the heating of the shocks).
constexpr double baseTimeStep = 0.25 * h / 2.0;

double W(double r) { return sph::cubic_spline::W<2>(r, h); }
double dW(double r) { return sph::cubic_spline::dWdr<2>(r, h); } // dW/dr

void Spawn() {
    const double mass = rho0 * spacing * spacing;
    for (int j = 0; j < side; j++)
        for (int i = 0; i < side; i++) {
            double x = (i + 0.5) * spacing, y = (j + 0.5) * spacing;
            wash::Vec2D vel{driftX + shear * std::sin(2 * PI * y) + compression * std::sin(2 * PI * x),
                            driftY + shear * std::sin(2 * PI * x)};
            wash::Particle& p = wash::create_particle(rho0, mass, h, wash::Vec2D{x, y}, vel);
            p.set_force_scalar("energy", energy0);
        }
}

// Kick-drift-kick leapfrog: the first half kick and the drift.
void KickDrift(wash::Particle& p) { sph::leapfrog_kick_drift(p, wash::get_variable("dt")); }

// Summation density, then pressure and sound speed from the ideal gas law. A
// negative internal energy (what too large a step leads to) gives a NaN
// sound speed, which the runtime reports.
void Density(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    double rho = p.get_mass() * W(0.0);
    for (const auto& n : neighbours)
        rho += n.get_mass() * W((p.get_pos() - n.get_pos()).magnitude());
    const double energy = p.get_force_scalar("energy");
    p.set_density(rho);
    p.set_force_scalar("pressure", sph::ideal_gas_pressure(adiabaticIndex, rho, energy));
    p.set_force_scalar("sound_speed",
                       sph::ideal_gas_sound_speed_from_energy(adiabaticIndex, energy));
}

// Pressure and viscous accelerations and du/dt. For the pair (i, j) both sides
// compute the same scalar factor, and gradW flips sign with d = x_i - x_j.
void Forces(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const wash::Vec2D pos = p.get_pos(), vel = p.get_vel();
    const double rhoi = p.get_density(), Pi = p.get_force_scalar("pressure");
    const double ci = p.get_force_scalar("sound_speed");
    wash::Vec2D acc{};
    double energyRate = 0.0;
    for (const auto& n : neighbours) {
        wash::Vec2D d = pos - n.get_pos();
        double r = d.magnitude();
        if (r <= 0.0) continue;
        const double rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
        const double cj = n.get_force_scalar("sound_speed");
        wash::Vec2D gradW = sph::gradient(d, r, dW(r));
        wash::Vec2D dv = vel - n.get_vel();
        double vr = dv.dot(d), viscosity = 0.0;
        if (vr < 0.0) {
            double mu = sph::monaghan_mu(h, vr, r);
            viscosity = sph::monaghan_viscosity(alphaAV, betaAV, ci, cj, mu, 0.5 * (rhoi + rhoj));
        }
        const double m = n.get_mass();
        acc -= gradW * sph::momentum_factor(m, Pi, rhoi, Pj, rhoj, viscosity);
        energyRate += sph::energy_factor(m, Pi, rhoi, viscosity) * dv.dot(gradW);
    }
    p.set_acc(acc);
    p.set_force_scalar("energy_rate", energyRate);
}

// Second half kick: the state at the end of the step.
void Kick(wash::Particle& p) { sph::leapfrog_kick(p, wash::get_variable("dt")); }

double TotalEnergy(const wash::Particle& p) {
    wash::Vec2D v = p.get_vel();
    return p.get_mass() * (0.5 * v.dot(v) + p.get_force_scalar("energy"));
}

double KineticEnergy(const wash::Particle& p) { return sph::kinetic_energy(p); }

double MomentumX(const wash::Particle& p) { return p.get_mass() * p.get_vel().at(0); }
double MomentumY(const wash::Particle& p) { return p.get_mass() * p.get_vel().at(1); }

// One line per step, then the clock: step 1 ran with dt = 0, every later one
// takes the full time step.
void Log() {
    const double step = wash::get_variable("step") + 1.0;
    const double time = wash::get_variable("time") + wash::get_variable("dt");
    std::printf("step=%.0f time=%.17g energy=%.17g kinetic=%.17g momentum_x=%.17g momentum_y=%.17g\n", step,
                time, wash::get_variable("total_energy"), wash::get_variable("kinetic"),
                wash::get_variable("momentum_x"), wash::get_variable("momentum_y"));
    std::fflush(stdout);
    wash::set_variable("time", time);
    wash::set_variable("step", step);
    wash::set_variable("dt", baseTimeStep * wash::get_variable("dt_factor"));
}

int main(int argc, char** argv) {
    double factor = argc > 1 ? std::atof(argv[1]) : 1.0;
    if (!(factor > 0.0)) {
        std::fprintf(stderr, "closed_box: dt_factor must be a positive number, not '%s'\n", argv[1]);
        return 2;
    }
    wash::set_precision("double");
    // Every particle's h is the same: the pairs within 2h = radius, in id order.
    wash::set_smoothing_length_support(2.0, wash::Support::Symmetric);
    wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, true});
    wash::set_simulation_name("closed_box");
    wash::add_variable("dt_factor", factor);
    wash::add_variable("dt", 0.0);
    wash::add_variable("time", 0.0);
    wash::add_variable("step", 0.0);
    wash::add_variable("total_energy", 0.0);
    wash::add_variable("kinetic", 0.0);
    wash::add_variable("momentum_x", 0.0);
    wash::add_variable("momentum_y", 0.0);
    wash::add_force("energy", 1);
    wash::add_force("pressure", 1);
    wash::add_force("sound_speed", 1);
    wash::add_force("energy_rate", 1);
    wash::add_force("vel_half", 2);
    wash::add_force("energy_half", 1);
    wash::add_init_kernel(&Spawn);
    wash::add_update_kernel(&KickDrift);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Kick);
    wash::add_reduction_kernel(&TotalEnergy, wash::Reduction::Sum, "total_energy");
    wash::add_reduction_kernel(&KineticEnergy, wash::Reduction::Sum, "kinetic");
    wash::add_reduction_kernel(&MomentumX, wash::Reduction::Sum, "momentum_x");
    wash::add_reduction_kernel(&MomentumY, wash::Reduction::Sum, "momentum_y");
    wash::add_void_kernel(&Log);
    wash::set_max_iterations(1001);
    wash::start();
    return 0;
}
