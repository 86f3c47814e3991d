// sedov: the Sedov-Taylor point blast in 3D (Sedov 1959), the standard SPH
// shock test of SPH-EXA (Cabezon et al. 2017).
//
// A periodic unit box of gas at rest (rho0 = 1, gamma = 5/3, negligible
// pressure) receives E = 1 of internal energy in a small Gaussian around its
// centre; a spherical shock runs out, r_s = 1.15167 (E t^2 / rho0)^(1/5), and
// the run stops at t = 0.05 (r_s = 0.3475). Standard SPH: Wendland C2 kernel
// with support 2h, summation density, smoothing lengths adapted to about 100
// neighbours, Monaghan (1992) artificial viscosity with a Balsara switch, the
// internal energy equation, kick-drift-kick leapfrog with a global time step
// from a Min reduction (Courant condition), and wash::stop() at the end time.
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
constexpr double ambientEnergy = 1e-8; // specific internal energy of the cold gas
constexpr double depositWidth = 0.1;   // the deposit is exp(-r^2 / w^2), w as in SPH-EXA
constexpr double endTime = 0.05;
constexpr double hFactor = 1.3;      // h = hFactor (m / rho)^(1/3): about 100 neighbours in 2h
constexpr double searchSupport = 2.5; // neighbours within 2.5 h_i: also those whose 2h_j reaches i
constexpr double hMaxFactor = 2.0;    // h stays within [h0 / hMaxFactor, hMaxFactor h0]
constexpr double courant = 0.3;
constexpr double alphaAV = 1.0; // Monaghan (1992) viscosity
constexpr double betaAV = 1.0;
constexpr double selfCorrection = 0.0294*1.36; // Dehnen & Aly (2012) density bias of Wendland C2 at 100 neighbours
constexpr bool useBalsara = true;
constexpr double alphaConductivity = 0.3; // Price (2008) artificial conductivity
constexpr bool conductOnlyReceding = true;
constexpr bool predictH = false;
constexpr bool useIAD = false;
constexpr wash::Vec3D centre{0.5, 0.5, 0.5};

constexpr int kernelChoice = 0; // 0 Wendland C2, 1 sinc^6

double W(double r, double h) {
    double q = r / h;
    if (q >= 2.0) return 0.0;
    if (kernelChoice == 0) {
        double s = 1.0 - 0.5 * q;
        return 21.0 / (16.0 * PI * h * h * h) * s * s * s * s * (1.0 + 2.0 * q);
    }
    double x = 0.5 * q, s = x > 0.0 ? std::sin(PI * x) / (PI * x) : 1.0;
    return 0.7904495894323025 / (h * h * h) * s * s * s * s * s * s;
}

double dW(double r, double h) { // dW/dr
    double q = r / h;
    if (q >= 2.0) return 0.0;
    if (kernelChoice == 0) {
        double s = 1.0 - 0.5 * q;
        return -21.0 / (16.0 * PI * h * h * h * h) * 5.0 * q * s * s * s;
    }
    double x = 0.5 * q;
    if (x <= 0.0) return 0.0;
    double s = std::sin(PI * x) / (PI * x), ds = (std::cos(PI * x) - s) / x;
    return 0.7904495894323025 / (h * h * h * h) * 3.0 * s * s * s * s * s * ds;
}

wash::Vec3D cross(const wash::Vec3D& a, const wash::Vec3D& b) {
    return wash::Vec3D{a.at(1) * b.at(2) - a.at(2) * b.at(1), a.at(2) * b.at(0) - a.at(0) * b.at(2),
                       a.at(0) * b.at(1) - a.at(1) * b.at(0)};
}

double soundSpeed(double energy) { return std::sqrt(adiabaticIndex * (adiabaticIndex - 1.0) * energy); }

double initialSmoothingLength() { return hFactor / wash::get_variable("side"); }

// The n^3 lattice, with the blast energy spread as exp(-r^2 / w^2) over the
// particles and normalised so that it adds up to exactly E.
void Spawn() {
    const int n = int(wash::get_variable("side"));
    const double dx = 1.0 / n, mass = rho0 * dx * dx * dx, h = initialSmoothingLength();
    const double width = depositWidth;
    double weights = 0.0;
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                wash::Vec3D d = wash::Vec3D{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx} - centre;
                weights += mass * std::exp(-d.dot(d) / (width * width));
            }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                wash::Vec3D pos{(i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx};
                wash::Vec3D d = pos - centre;
                double u = ambientEnergy + blastEnergy * std::exp(-d.dot(d) / (width * width)) / weights;
                wash::Particle& p = wash::create_particle(rho0, mass, h, pos, wash::Vec3D{});
                p.set_force_scalar("energy", u);
                p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * rho0 * u);
            }
}

// First half kick and drift: vel and energy become the predicted full-step
// values the force kernels see; the half-step values wait for the second kick.
void KickDrift(wash::Particle& p) {
    const double dt = wash::get_variable("dt");
    wash::Vec3D velHalf = p.get_vel() + p.get_acc() * (0.5 * dt);
    double energyHalf = p.get_force_scalar("energy") + p.get_force_scalar("energy_rate") * (0.5 * dt);
    p.set_pos(p.get_pos() + velHalf * dt);
    if (predictH) p.set_smoothing_length(p.get_smoothing_length() * std::exp(-p.get_force_scalar("div_v") * dt / 3.0));
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
    double rho = (1.0 - selfCorrection) * p.get_mass() * W(0.0, h), div = 0.0;
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
    const double energy = p.get_force_scalar("energy"), c = soundSpeed(energy);
    div /= rho;
    const double curlMagnitude = curl.magnitude() / rho;
    p.set_density(rho);
    p.set_force_scalar("div_v", div);
    p.set_force_scalar("pressure", (adiabaticIndex - 1.0) * rho * energy);
    p.set_force_scalar("balsara",
                       std::abs(div) / (std::abs(div) + curlMagnitude + 1e-4 * c / h));
}

// Integral approach to derivatives (Garcia-Senz et al. 2012): C_i, the inverse
// of tau_i = sum_j V_j (x_j - x_i)(x_j - x_i)^T W_ij(h_i), V_j = m_j / rho_j.
void Gradients(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const double h = p.get_smoothing_length();
    const wash::Vec3D pos = p.get_pos();
    double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, xz = 0.0, yz = 0.0;
    for (const auto& n : neighbours) {
        wash::Vec3D d = n.get_pos() - pos;
        double r = d.magnitude();
        if (r >= 2.0 * h) continue;
        double w = n.get_mass() / n.get_density() * W(r, h);
        double dx = d.at(0), dy = d.at(1), dz = d.at(2);
        xx += dx * dx * w; yy += dy * dy * w; zz += dz * dz * w;
        xy += dx * dy * w; xz += dx * dz * w; yz += dy * dz * w;
    }
    double det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
    p.set_force_vector("iad_diag", wash::Vec3D{(yy * zz - yz * yz) / det, (xx * zz - xz * xz) / det,
                                               (xx * yy - xy * xy) / det});
    p.set_force_vector("iad_off", wash::Vec3D{(xz * yz - xy * zz) / det, (xy * xz - yz * xx) / det,
                                              (xy * yz - xz * yy) / det});
}

wash::Vec3D applyIAD(const wash::Vec3D& diag, const wash::Vec3D& off, const wash::Vec3D& v) {
    return wash::Vec3D{diag.at(0) * v.at(0) + off.at(0) * v.at(1) + off.at(1) * v.at(2),
                       off.at(0) * v.at(0) + diag.at(1) * v.at(1) + off.at(2) * v.at(2),
                       off.at(1) * v.at(0) + off.at(2) * v.at(1) + diag.at(2) * v.at(2)};
}

// Pressure and viscous accelerations, du/dt, and the particle's time step.
void Forces(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const wash::Vec3D pos = p.get_pos(), vel = p.get_vel();
    const double hi = p.get_smoothing_length(), rhoi = p.get_density();
    const double Pi = p.get_force_scalar("pressure"), ci = std::sqrt(adiabaticIndex * Pi / rhoi);
    const double fi = p.get_force_scalar("balsara");
    wash::Vec3D acc{};
    double energyRate = 0.0, vsig = ci;
    for (const auto& n : neighbours) {
        wash::Vec3D d = pos - n.get_pos();
        double r = d.magnitude();
        const double hj = n.get_smoothing_length();
        // a pair interacts only if each particle is in the other's search
        // sphere, so that both see the same pair forces (and conserve energy)
        if (r <= 0.0 || d.dot(d) > (searchSupport * hj) * (searchSupport * hj)) continue;
        const double rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
        const double cj = std::sqrt(adiabaticIndex * Pj / rhoj);
        wash::Vec3D gradW = d * (0.5 * (dW(r, hi) + dW(r, hj)) / r);
        if (useIAD)
            gradW = (applyIAD(p.get_force_vector("iad_diag"), p.get_force_vector("iad_off"), -d) * W(r, hi) +
                     applyIAD(n.get_force_vector("iad_diag"), n.get_force_vector("iad_off"), -d) * W(r, hj)) * 0.5;
        wash::Vec3D dv = vel - n.get_vel();
        double vr = dv.dot(d), viscosity = 0.0;
        if (vr < 0.0) {
            double hij = 0.5 * (hi + hj);
            double mu = hij * vr / (r * r + 0.01 * hij * hij);
            double fij = useBalsara ? 0.5 * (fi + n.get_force_scalar("balsara")) : 1.0;
            viscosity = fij * (-alphaAV * 0.5 * (ci + cj) * mu + betaAV * mu * mu) / (0.5 * (rhoi + rhoj));
            vsig = std::max(vsig, ci + cj - 3.0 * vr / r);
        } else {
            vsig = std::max(vsig, ci + cj);
        }
        const double m = n.get_mass();
        acc -= gradW * (m * (Pi / (rhoi * rhoi) + Pj / (rhoj * rhoj) + viscosity));
        energyRate += m * (Pi / (rhoi * rhoi) + 0.5 * viscosity) * dv.dot(gradW);
        // conduction: u flows down its gradient at speed sqrt(|dP| / rho)
        double rhoij = 0.5 * (rhoi + rhoj);
        double ui = Pi / ((adiabaticIndex - 1.0) * rhoi), uj = Pj / ((adiabaticIndex - 1.0) * rhoj);
        if (!conductOnlyReceding || vr >= 0.0)
        energyRate += m * alphaConductivity * std::sqrt(std::abs(Pi - Pj) / rhoij) * (ui - uj) / rhoij *
                      0.5 * (dW(r, hi) + dW(r, hj));
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
    const double h0 = initialSmoothingLength();
    double h = hFactor * std::cbrt(p.get_mass() / p.get_density());
    p.set_smoothing_length(std::min(std::max(h, h0 / hMaxFactor), hMaxFactor * h0));
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
    if (side < 4) side = defaultSide;
    wash::set_precision("double");
    wash::set_smoothing_length_support(searchSupport);
    wash::set_bounding_box({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {true, true, true});
    wash::set_simulation_name("sedov");
    wash::add_variable("side", side);
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
    wash::add_init_kernel(&Spawn);
    wash::add_update_kernel(&KickDrift);
    wash::add_force_kernel(&Density);
    if (useIAD) wash::add_force_kernel(&Gradients);
    wash::add_force_kernel(&Forces);
    wash::add_update_kernel(&Kick);
    wash::add_reduction_kernel(&TimeStep, wash::Reduction::Min, "next_dt");
    wash::add_void_kernel(&Clock);
    wash::set_max_iterations(1000000);
    wash::start();
    return 0;
}
