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

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

constexpr int defaultSide = 30;
constexpr double adiabaticIndex = 5.0 / 3.0;
constexpr double blastEnergy = 1.0;
constexpr double rho0 = 1.0;
constexpr double ambientEnergy = 1e-8;    // specific internal energy of the cold gas
constexpr double depositWidth = 0.1;      // the deposit is exp(-r^2 / w^2), w as in SPH-EXA
constexpr double endTime = 0.05;
constexpr double hFactor = 1.3;           // h = hFactor (m / rho)^(1/3): 74 neighbours within 2h
constexpr double searchSupport = 2.5;     // neighbours within 2.5 h_i: those whose 2h_j reaches i too
constexpr double hRange = 2.0;            // h stays within [h0 / hRange, hRange h0]
constexpr double courant = 0.3;
constexpr double alphaAV = 1.0;           // Monaghan (1992) viscosity
constexpr double betaAV = 1.0;
constexpr double alphaConductivity = 0.3; // Price (2008) artificial conductivity
constexpr wash::Vec3D centre{0.5, 0.5, 0.5};

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

double initialSpacing() { return 1.0 / wash::get_variable("side"); }

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
                p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * rho0 * u);
            }
}

// First half kick and drift: vel and energy become the predicted full-step
// values the force kernels see; the half-step values wait for the second kick.
void KickDrift(wash::Particle& p) {
    const double dt = wash::get_time_step();
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
    const double dt = wash::get_time_step();
    p.set_vel(p.get_force_vector("vel_half") + p.get_acc() * (0.5 * dt));
    double energy = p.get_force_scalar("energy_half") + p.get_force_scalar("energy_rate") * (0.5 * dt);
    p.set_force_scalar("energy", energy);
    p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * p.get_density() * energy);
    const double h0 = hFactor * initialSpacing();
    double h = hFactor * std::cbrt(p.get_mass() / p.get_density());
    p.set_smoothing_length(std::min(std::max(h, h0 / hRange), hRange * h0));
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
    wash::set_smoothing_length_support(searchSupport);
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
