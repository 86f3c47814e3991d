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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

constexpr int defaultSide = 30;
constexpr double radius = 1.0;            // of the initial sphere
constexpr double adiabaticIndex = 5.0 / 3.0;
constexpr double rho0 = 1.0;
constexpr double inflowSpeed = 1.0;
constexpr double ambientEnergy = 1e-6;    // specific internal energy of the cold gas
constexpr double endTime = 0.6;
constexpr double hFactor = 1.3;           // h = hFactor (m / rho)^(1/3): 74 neighbours within 2h
constexpr double searchSupport = 2.5;     // neighbours within 2.5 h_i: those whose 2h_j reaches i too
constexpr double hMinFactor = 0.125;      // h stays within [hMinFactor h0, hMaxFactor h0]
constexpr double hMaxFactor = 2.0;        // (the shocked gas is 64 times denser: h = h0 / 4)
constexpr double courant = 0.3;
constexpr double alphaAV = 1.0;           // Monaghan (1992) viscosity
constexpr double betaAV = 1.0;
constexpr double alphaConductivity = 0.3; // Price (2008) artificial conductivity

// Wendland C2 in 3D with support 2h (Wendland 1995; Dehnen & Aly 2012), q = r / h.
double W(double r, double h) {
    double q = r / h;
    if (q >= 2.0) return 0.0;
    double s = 1.0 - 0.5 * q;
    return 21.0 / (16.0 * PI * h * h * h) * s * s * s * s * (1.0 + 2.0 * q);
}

double dW(double r, double h) { // dW/dr
    double q = r / h;
    if (q >= 2.0) return 0.0;
    double s = 1.0 - 0.5 * q;
    return -105.0 / (16.0 * PI * h * h * h * h) * q * s * s * s;
}

wash::Vec3D cross(const wash::Vec3D& a, const wash::Vec3D& b) {
    return wash::Vec3D{a.at(1) * b.at(2) - a.at(2) * b.at(1), a.at(2) * b.at(0) - a.at(0) * b.at(2),
                       a.at(0) * b.at(1) - a.at(1) * b.at(0)};
}

double soundSpeed(double pressure, double density) {
    return std::sqrt(adiabaticIndex * pressure / density);
}

double initialSpacing() { return 2.0 * radius / wash::get_variable("side"); }

// The fraction of its own kernel weight a particle leaves out of its density
// (Dehnen & Aly 2012 correct the bias of Wendland kernels this way): chosen
// so that the initial lattice has density rho0 exactly.
void CalibrateDensity() {
    const double dx = initialSpacing(), mass = rho0 * dx * dx * dx, h = hFactor * dx;
    double lattice = 0.0;
    for (int k = -3; k <= 3; k++)
        for (int j = -3; j <= 3; j++)
            for (int i = -3; i <= 3; i++)
                lattice += mass * W(dx * std::sqrt(double(i * i + j * j + k * k)), h);
    wash::set_variable("self_correction", (lattice - rho0) / (mass * W(0.0, h)));
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
                p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * rho0 * ambientEnergy);
            }
}

// First half kick and drift: vel and energy become the predicted full-step
// values the force kernels see; the half-step values wait for the second kick.
void KickDrift(wash::Particle& p) {
    const double dt = wash::get_variable("dt");
    wash::Vec3D velHalf = p.get_vel() + p.get_acc() * (0.5 * dt);
    double energyHalf = p.get_force_scalar("energy") + p.get_force_scalar("energy_rate") * (0.5 * dt);
    p.set_pos(p.get_pos() + velHalf * dt);
    p.set_force_vector("vel_half", velHalf);
    p.set_force_scalar("energy_half", energyHalf);
    p.set_vel(velHalf + p.get_acc() * (0.5 * dt));
    p.set_force_scalar("energy", energyHalf + p.get_force_scalar("energy_rate") * (0.5 * dt));
}

// Summation density, pressure, and the Balsara (1995) switch from the
// velocity divergence and curl.
void Density(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const double h = p.get_smoothing_length();
    const wash::Vec3D pos = p.get_pos(), vel = p.get_vel();
    double rho = (1.0 - wash::get_variable("self_correction")) * p.get_mass() * W(0.0, h);
    double div = 0.0;
    wash::Vec3D curl{};
    for (const auto& n : neighbours) {
        wash::Vec3D d = pos - n.get_pos();
        double r = d.magnitude();
        if (r >= 2.0 * h || r <= 0.0) continue;
        rho += n.get_mass() * W(r, h);
        wash::Vec3D gradW = d * (dW(r, h) / r);
        wash::Vec3D dv = vel - n.get_vel();
        div -= n.get_mass() * dv.dot(gradW);
        curl += cross(dv, gradW) * n.get_mass();
    }
    const double energy = p.get_force_scalar("energy"), pressure = (adiabaticIndex - 1.0) * rho * energy;
    div /= rho;
    const double curlMagnitude = curl.magnitude() / rho;
    p.set_density(rho);
    p.set_force_scalar("pressure", pressure);
    p.set_force_scalar("balsara", std::abs(div) / (std::abs(div) + curlMagnitude +
                                                   1e-4 * soundSpeed(pressure, rho) / h));
}

// Pressure and viscous accelerations, du/dt (with conduction), and the
// particle's time step.
void Forces(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const wash::Vec3D pos = p.get_pos(), vel = p.get_vel();
    const double hi = p.get_smoothing_length(), rhoi = p.get_density();
    const double Pi = p.get_force_scalar("pressure"), ci = soundSpeed(Pi, rhoi);
    const double ui = Pi / ((adiabaticIndex - 1.0) * rhoi), fi = p.get_force_scalar("balsara");
    wash::Vec3D acc{};
    double energyRate = 0.0, vsig = ci;
    for (const auto& n : neighbours) {
        wash::Vec3D d = pos - n.get_pos();
        const double r = d.magnitude(), hj = n.get_smoothing_length();
        // A pair interacts only if each particle is in the other's search
        // sphere: both then add the same pair terms, which conserves momentum
        // and energy.
        if (r <= 0.0 || d.dot(d) > (searchSupport * hj) * (searchSupport * hj)) continue;
        const double m = n.get_mass(), rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
        const double cj = soundSpeed(Pj, rhoj), uj = Pj / ((adiabaticIndex - 1.0) * rhoj);
        const double dWij = 0.5 * (dW(r, hi) + dW(r, hj)); // symmetrised kernel gradient
        const wash::Vec3D gradW = d * (dWij / r), dv = vel - n.get_vel();
        const double vr = dv.dot(d), rhoij = 0.5 * (rhoi + rhoj);
        double viscosity = 0.0;
        if (vr < 0.0) { // approaching
            double hij = 0.5 * (hi + hj), mu = hij * vr / (r * r + 0.01 * hij * hij);
            double balsara = 0.5 * (fi + n.get_force_scalar("balsara"));
            viscosity = balsara * (-alphaAV * 0.5 * (ci + cj) * mu + betaAV * mu * mu) / rhoij;
            vsig = std::max(vsig, ci + cj - 3.0 * vr / r);
        } else {
            vsig = std::max(vsig, ci + cj);
        }
        acc -= gradW * (m * (Pi / (rhoi * rhoi) + Pj / (rhoj * rhoj) + viscosity));
        energyRate += m * (Pi / (rhoi * rhoi) + 0.5 * viscosity) * dv.dot(gradW);
        // conduction: u diffuses down its gradient at speed sqrt(|P_i - P_j| / rho)
        energyRate += m * alphaConductivity * std::sqrt(std::abs(Pi - Pj) / rhoij) * (ui - uj) /
                      rhoij * dWij;
    }
    p.set_acc(acc);
    p.set_force_scalar("energy_rate", energyRate);
    p.set_force_scalar("time_step", courant * hi / vsig);
}

// Second half kick, then the smoothing length for the next step.
void Kick(wash::Particle& p) {
    const double dt = wash::get_variable("dt");
    p.set_vel(p.get_force_vector("vel_half") + p.get_acc() * (0.5 * dt));
    double energy = p.get_force_scalar("energy_half") + p.get_force_scalar("energy_rate") * (0.5 * dt);
    p.set_force_scalar("energy", energy);
    p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * p.get_density() * energy);
    const double h0 = hFactor * initialSpacing();
    double h = hFactor * std::cbrt(p.get_mass() / p.get_density());
    p.set_smoothing_length(std::min(std::max(h, hMinFactor * h0), hMaxFactor * h0));
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
    wash::set_smoothing_length_support(searchSupport);
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
