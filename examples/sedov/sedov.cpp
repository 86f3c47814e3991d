// sedov: the Sedov-Taylor point blast in 3D (Sedov 1959), the standard SPH
// shock test of SPH-EXA (Cabezon et al. 2017).
//
// A periodic unit box of gas at rest (rho0 = 1, gamma = 5/3, negligible
// pressure) receives E = 1 of internal energy in a Gaussian of width 0.1 at
// its centre; a spherical shock runs out, r_s = 1.15167 (E t^2 / rho0)^(1/5),
// and the run stops at t = 0.05 (r_s = 0.3475). Standard SPH: Wendland C2
// kernel with support 2h, summation density, smoothing lengths adapted to
// about 74 neighbours, Monaghan (1992) artificial viscosity with a Balsara
// switch, Price (2008) artificial conductivity, the internal energy equation,
// kick-drift-kick leapfrog with a global time step from a Min reduction into
// the runtime's time step (the Courant condition); the run ends at t = 0.05
// (wash::set_end_time; --end-time overrides it). See README.md.
//
//   sedov [n]   an n^3 lattice (default 30)
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
constexpr double adiabaticIndex = 5.0 / 3.0;
constexpr double blastEnergy = 1.0;
constexpr double rho0 = 1.0;
constexpr double ambientEnergy = 1e-8;    // specific internal energy of the cold gas
constexpr double depositWidth = 0.1;      // the deposit is exp(-r^2 / w^2), w as in SPH-EXA
constexpr double endTime = 0.05;
constexpr double hFactor = 1.3;           // h = hFactor (m / rho)^(1/3): 74 neighbours within 2h
constexpr double searchSupport = 2.0;     // neighbours within 2 max(h_i, h_j): the pairs either kernel reaches
constexpr double hRange = 2.0;            // h stays within [h0 / hRange, hRange h0]
constexpr double courant = 0.3;
constexpr double alphaAV = 1.0;           // Monaghan (1992) viscosity
constexpr double betaAV = 1.0;
constexpr double alphaConductivity = 0.3; // Price (2008) artificial conductivity
constexpr sph::GasScheme scheme{adiabaticIndex, alphaAV, betaAV, alphaConductivity, courant,
                                searchSupport, wash::Support::Symmetric};
constexpr wash::Vec3D centre{0.5, 0.5, 0.5};

double initialSpacing() { return 1.0 / wash::get_variable("side"); }

// The self-correction of summation density for the initial lattice.
void CalibrateDensity() {
    const double dx = initialSpacing();
    wash::set_variable("self_correction", sph::wendland_c2_self_correction<3>(dx, hFactor * dx, rho0));
}

// The n^3 lattice, with the blast energy spread as exp(-r^2 / w^2) over the
// particles and normalised so that it adds up to exactly E.
void Spawn() {
    const int n = int(wash::get_variable("side"));
    const double dx = initialSpacing(), mass = rho0 * dx * dx * dx, h = hFactor * dx;
    double weights = 0.0;
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                wash::Vec3D d = wash::Vec3D{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx} - centre;
                weights += mass * std::exp(-d.dot(d) / (depositWidth * depositWidth));
            }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                wash::Vec3D pos{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx};
                wash::Vec3D d = pos - centre;
                double u = ambientEnergy +
                           blastEnergy * std::exp(-d.dot(d) / (depositWidth * depositWidth)) / weights;
                wash::Particle& p = wash::create_particle(rho0, mass, h, pos, wash::Vec3D{});
                p.set_force_scalar("energy", u);
                p.set_force_scalar("pressure", sph::ideal_gas_pressure(adiabaticIndex, rho0, u));
            }
}

// Kick-drift-kick leapfrog: the first half kick and the drift.
void KickDrift(wash::Particle& p) { sph::leapfrog_kick_drift(p, wash::get_time_step()); }

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
    const double energy = sph::leapfrog_kick(p, wash::get_time_step());
    p.set_force_scalar("pressure",
                       sph::ideal_gas_pressure(adiabaticIndex, p.get_density(), energy));
    const double h0 = hFactor * initialSpacing();
    sph::gas_smoothing_length(p, hFactor, h0 / hRange, hRange * h0);
}

// The Courant time step of the forces of the previous iteration. The first
// iteration has none yet (every particle's time_step is 0), so it has dt = 0:
// it only evaluates the forces of the initial state.
double TimeStep(const wash::Particle& p) { return p.get_force_scalar("time_step"); }

// The last step is shortened to end exactly at the end time.
void LastStep() {
    wash::set_time_step(std::min(wash::get_time_step(), wash::get_end_time() - wash::get_time()));
}

int main(int argc, char** argv) {
    int side = argc > 1 ? std::atoi(argv[1]) : defaultSide;
    if (side < 8) side = defaultSide;
    wash::set_precision("double");
    wash::set_smoothing_length_support(searchSupport, wash::Support::Symmetric);
    wash::set_bounding_box({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {true, true, true});
    wash::set_simulation_name("sedov");
    wash::add_variable("side", side);
    wash::add_variable("self_correction", 0.0);
    wash::add_force("pressure", 1);
    wash::add_force("energy", 1);
    wash::add_force("energy_rate", 1);
    wash::add_force("balsara", 1);
    wash::add_force("time_step", 1);
    wash::add_force("vel_half", 3);
    wash::add_force("energy_half", 1);
    wash::add_init_kernel(&CalibrateDensity);
    wash::add_init_kernel(&Spawn);
    wash::add_reduction_kernel(&TimeStep, wash::Reduction::Min, "time_step");
    wash::add_void_kernel(&LastStep);
    wash::add_update_kernel(&KickDrift);
    wash::add_force_kernel(&Density);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Kick);
    wash::set_end_time(endTime);
    wash::start();
    return 0;
}
