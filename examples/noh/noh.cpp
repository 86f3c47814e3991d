// noh: the Noh implosion in 3D (Noh 1987), a hard shock test for SPH.
//
// A sphere of cold gas (rho0 = 1, gamma = 5/3, negligible pressure) flows
// radially inward at speed 1. A shock forms at the centre and runs out at
// speed 1/3; behind it the gas is at rest with density 64 and pressure 64/3,
// ahead of it the density is (1 + t / r)^2. The run stops at t = 0.6 (shock at
// r = 0.2). The SPH scheme is the one of examples/sedov: Wendland C2 kernel
// with support 2h, summation density, smoothing lengths adapted to about 74
// neighbours, Monaghan (1992) artificial viscosity with a Balsara switch,
// Price (2008) artificial conductivity, the internal energy equation,
// kick-drift-kick leapfrog with a global time step from a Min reduction (the
// Courant condition), and wash::stop() at the end time. There is no box: the
// sphere's outer edge is free (cold gas has no pressure to push it out), and
// only the inner part is compared with the exact solution. See README.md.
//
//   noh [n]   the points of an n^3 lattice on [-1, 1]^3 that lie inside the
//             unit sphere (default 30: 14,328 particles)
#include <wash/wash.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/gas.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/leapfrog.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace sph = wash::sph;

constexpr int defaultSide = 30;
constexpr double radius = 1.0;            // of the initial sphere
constexpr double adiabaticIndex = 5.0 / 3.0;
constexpr double rho0 = 1.0;
constexpr double inflowSpeed = 1.0;
constexpr double ambientEnergy = 1e-6;    // specific internal energy of the cold gas
constexpr double endTime = 0.6;
constexpr double hFactor = 1.3;           // h = hFactor (m / rho)^(1/3): 74 neighbours within 2h
constexpr double searchSupport = 2.0;     // neighbours within 2 max(h_i, h_j): the pairs either kernel reaches
constexpr double hMinFactor = 0.125;      // h stays within [hMinFactor h0, hMaxFactor h0]
constexpr double hMaxFactor = 2.0;        // (the shocked gas is 64 times denser: h = h0 / 4)
constexpr double courant = 0.3;
constexpr double alphaAV = 1.0;           // Monaghan (1992) viscosity
constexpr double betaAV = 1.0;
constexpr double alphaConductivity = 0.3; // Price (2008) artificial conductivity
constexpr sph::GasScheme scheme{adiabaticIndex, alphaAV, betaAV, alphaConductivity, courant,
                                searchSupport, wash::Support::Symmetric};

double initialSpacing() { return 2.0 * radius / wash::get_variable("side"); }

// The self-correction of summation density for the initial lattice.
void CalibrateDensity() {
    const double dx = initialSpacing();
    wash::set_variable("self_correction", sph::wendland_c2_self_correction<3>(dx, hFactor * dx, rho0));
}

// The points of the n^3 lattice on [-R, R]^3 (none at the centre) inside the
// sphere of radius R, all moving towards the centre at the inflow speed.
void Spawn() {
    const int n = int(wash::get_variable("side"));
    const double dx = initialSpacing(), mass = rho0 * dx * dx * dx, h = hFactor * dx;
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                wash::Vec3D pos{(i + 0.5) * dx - radius, (j + 0.5) * dx - radius,
                                (k + 0.5) * dx - radius};
                const double r = pos.magnitude();
                if (r > radius) continue;
                wash::Particle& p =
                    wash::create_particle(rho0, mass, h, pos, pos * (-inflowSpeed / r));
                p.set_force_scalar("energy", ambientEnergy);
                p.set_force_scalar("pressure",
                                   sph::ideal_gas_pressure(adiabaticIndex, rho0, ambientEnergy));
            }
}

// Kick-drift-kick leapfrog: the first half kick and the drift.
void KickDrift(wash::Particle& p) { sph::leapfrog_kick_drift(p, wash::get_variable("dt")); }

// Summation density, pressure, and the Balsara (1995) switch.
void Density(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    sph::gas_density(p, neighbours, scheme, wash::get_variable("self_correction"));
}

// Pressure and viscous accelerations, du/dt (with conduction), and the
// particle's time step.
void Forces(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    sph::gas_forces(p, neighbours, scheme);
}

// Second half kick, then the smoothing length for the next step.
void Kick(wash::Particle& p) {
    const double energy = sph::leapfrog_kick(p, wash::get_variable("dt"));
    p.set_force_scalar("pressure",
                       sph::ideal_gas_pressure(adiabaticIndex, p.get_density(), energy));
    const double h0 = hFactor * initialSpacing();
    sph::gas_smoothing_length(p, hFactor, hMinFactor * h0, hMaxFactor * h0);
}

double TimeStep(const wash::Particle& p) { return p.get_force_scalar("time_step"); }

// The clock: the first iteration has dt = 0 (it only evaluates the forces of
// the initial state), then each step takes the Courant time step, the last one
// shortened to end exactly at endTime.
void Clock() {
    const double time = wash::get_variable("time") + wash::get_variable("dt");
    wash::set_variable("time", time);
    if (time >= endTime * (1.0 - 1e-12)) {
        wash::stop();
        return;
    }
    wash::set_variable("dt", std::min(wash::get_variable("next_dt"), endTime - time));
}

int main(int argc, char** argv) {
    int side = argc > 1 ? std::atoi(argv[1]) : defaultSide;
    if (side < 8) side = defaultSide;
    wash::set_precision("double");
    wash::set_smoothing_length_support(searchSupport, wash::Support::Symmetric);
    wash::set_simulation_name("noh");
    wash::add_variable("side", side);
    wash::add_variable("self_correction", 0.0);
    wash::add_variable("time", 0.0);
    wash::add_variable("dt", 0.0);
    wash::add_variable("next_dt", 0.0);
    wash::add_force("pressure", 1);
    wash::add_force("energy", 1);
    wash::add_force("energy_rate", 1);
    wash::add_force("balsara", 1);
    wash::add_force("time_step", 1);
    wash::add_force("vel_half", 3);
    wash::add_force("energy_half", 1);
    wash::add_init_kernel(&CalibrateDensity);
    wash::add_init_kernel(&Spawn);
    wash::add_update_kernel(&KickDrift);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Kick);
    wash::add_reduction_kernel(&TimeStep, wash::Reduction::Min, "next_dt");
    wash::add_void_kernel(&Clock);
    wash::set_max_iterations(1000000);
    wash::start();
    return 0;
}
