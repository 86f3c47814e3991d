// dam_break_2d: the collapse of a water column (Martin & Moyce 1952), the
// standard validation of free-surface SPH.
//
// A column L = 1 wide and 2L high stands at rest at the left of a tank 4L wide
// and 3L high, g = 9.81. Weakly compressible SPH built from wash/sph: Wendland
// C2 kernel (support 2h, h = 1.5 dx), the continuity equation with delta-SPH
// density diffusion (Molteni & Colagrossi 2009), Tait's equation of state with
// c0 = 10 sqrt(2 g H), Monaghan (1992) artificial viscosity, fixed wall
// particles with the Adami, Hu & Adams (2012) boundary (scene/walls.hpp),
// kick-drift-kick leapfrog with a time step from the Courant and force criteria (a
// Min reduction into the runtime's time step). The run ends at T =
// t sqrt(2g/L) = 3.2 (t = 0.72 s); validate.sh plots the surge front against
// the experiments. See README.md.
//
//   dam_break_2d [n [w]]   n particles across the column (default 20; dx = L / n),
//                          a tank w L wide (default 4; w = 1: a column at rest)
#include <wash/wash.hpp>
#include <wash/sph/dissipation.hpp>
#include <wash/sph/eos.hpp>
#include <wash/sph/kernels.hpp>
#include <wash/sph/time_step.hpp>

#include "scene/walls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace sph = wash::sph;

constexpr int defaultColumn = 20;
constexpr double L = 1.0;             // column width
constexpr double H = 2.0 * L;         // column height
constexpr double defaultTankWidth = 4.0 * L;
constexpr double tankHeight = 3.0 * L;
constexpr int wallLayers = 3;         // 3 dx: the support 2h
constexpr double g = 9.81;
constexpr double rho0 = 1000.0;
constexpr double hFactor = 1.5;       // h = hFactor dx
constexpr double alphaAV = 0.1;       // Monaghan viscosity (beta = 0)
constexpr double deltaSph = 0.1;      // Molteni-Colagrossi density diffusion
constexpr double courant = 0.25;
constexpr double endT = 3.2;          // in units of sqrt(L / 2g)
constexpr double reportT = 0.1;       // the front is printed every 0.1 in T
const wash::Vec2D gravity{0.0, -g};

double SoundSpeed0() { return 10.0 * std::sqrt(2.0 * g * H); }
sph::Tait Water() { return sph::Tait{rho0, SoundSpeed0()}; }
double Spacing() { return L / wash::get_variable("column"); }

void Spawn() {
    const double dx = Spacing(), h = hFactor * dx, mass = rho0 * dx * dx;
    const sph::Tait eos = Water();
    const int nx = int(std::lround(L / dx)), ny = int(std::lround(H / dx));
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) { // the column, in hydrostatic equilibrium
            const double y = (j + 0.5) * dx, pressure = rho0 * g * (H - y);
            const wash::Vec2D pos{(i + 0.5) * dx, y};
            wash::Particle& p = wash::create_particle(eos.density(pressure), mass, h, pos, wash::Vec2D{});
            p.set_force_scalar("pressure", pressure);
        }
    const double width = wash::get_variable("tank_width");
    for (const wash::Vec2D& pos : WallPositions(width, tankHeight, dx, wallLayers)) {
        wash::Particle& p = wash::create_particle(rho0, mass, h, pos, wash::Vec2D{});
        p.set_type("wall");
    }
}

// Kick-drift-kick leapfrog for velocity and density, as wash/sph/leapfrog.hpp
// does it for velocity and energy: the first half kick and the drift, with
// the rates of the previous iteration; vel and density become the predicted
// full-step values the force kernels see. Walls stay where they are.
void KickDrift(wash::Particle& p) {
    const double dt = wash::get_time_step();
    const wash::Vec2D velHalf = p.get_vel() + p.get_acc() * (0.5 * dt);
    const double rhoHalf = p.get_density() + p.get_force_scalar("density_rate") * (0.5 * dt);
    p.set_pos(p.get_pos() + velHalf * dt);
    p.set_force_vector("vel_half", velHalf);
    p.set_force_scalar("density_half", rhoHalf);
    p.set_vel(velHalf + p.get_acc() * (0.5 * dt));
    const double rho = rhoHalf + p.get_force_scalar("density_rate") * (0.5 * dt);
    p.set_density(rho);
    p.set_force_scalar("pressure", Water().pressure(rho));
}

// The second half kick, with the new rates.
void Kick(wash::Particle& p) {
    const double dt = wash::get_time_step();
    p.set_vel(p.get_force_vector("vel_half") + p.get_acc() * (0.5 * dt));
    const double rho =
        p.get_force_scalar("density_half") + p.get_force_scalar("density_rate") * (0.5 * dt);
    p.set_density(rho);
    p.set_force_scalar("pressure", Water().pressure(rho));
}

void Walls(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    ExtrapolateToWall(p, neighbours, Water(), gravity);
}

// Continuity with delta-SPH, the pressure and viscous accelerations, and the
// particle's time step.
void Rates(wash::Particle& p, const std::vector<wash::Particle>& neighbours) {
    const sph::Tait eos = Water();
    const double c0 = eos.c0, h = p.get_smoothing_length(), rhoi = p.get_density();
    const double Pi = p.get_force_scalar("pressure"), ci = eos.sound_speed(rhoi);
    const wash::Vec2D pos = p.get_pos(), vel = p.get_vel();
    wash::Vec2D acc{};
    double densityRate = 0.0;
    for (const auto& n : neighbours) {
        const wash::Vec2D d = pos - n.get_pos();
        const double r = d.magnitude();
        if (r <= 0.0 || r >= sph::wendland_c2::support * h) continue;
        const bool wall = IsWall(n);
        const double m = n.get_mass(), rhoj = n.get_density(), Pj = n.get_force_scalar("pressure");
        const double dWdr = sph::wendland_c2::dWdr<2>(r, h);
        const wash::Vec2D gradW = sph::gradient(d, r, dWdr);
        densityRate += m * (vel - n.get_vel()).dot(gradW);
        if (!wall) densityRate += sph::delta_sph_diffusion(deltaSph, h, c0, rhoi, rhoj, m, r, dWdr);
        // Viscosity sees a wall at its no-slip velocity (Adami et al. 2012).
        const wash::Vec2D dv = vel - (wall ? n.get_force_vector("wall_vel") : n.get_vel());
        const double vr = dv.dot(d);
        double viscosity = 0.0;
        if (vr < 0.0)
            viscosity = sph::monaghan_viscosity(alphaAV, 0.0, ci, eos.sound_speed(rhoj),
                                                sph::monaghan_mu(h, vr, r), 0.5 * (rhoi + rhoj));
        acc -= gradW * sph::momentum_factor(m, Pi, rhoi, Pj, rhoj, viscosity);
    }
    acc += gravity;
    p.set_acc(acc);
    p.set_force_scalar("density_rate", densityRate);
    const double vsig = ci + vel.magnitude();
    p.set_force_scalar("time_step", std::min(sph::courant_time_step(courant, h, vsig),
                                             sph::force_time_step(courant, h, acc.magnitude())));
}

// The smallest time step of the previous iteration's rates. The first
// iteration has none yet (every time_step is 0), so it has dt = 0: it only
// evaluates the rates of the initial state. Over the fluid: walls do not limit it.
double TimeStep(const wash::Particle& p) { return p.get_force_scalar("time_step"); }

// The last step ends exactly at the end time.
void LastStep() {
    wash::set_time_step(std::min(wash::get_time_step(), wash::get_end_time() - wash::get_time()));
}

// The surge front: the rightmost fluid particle's centre, plus half a spacing
// for the edge of the fluid it stands for (the column starts at x = L).
double Front(const wash::Particle& p) { return p.get_pos().at(0); }

// Prints "front T=<t sqrt(2g/L)> x/L=<front / L>" each time T crosses a
// multiple of reportT (what validate.sh plots), at the end of the iteration.
void Report() {
    const double t = wash::get_time() + wash::get_time_step(), T = t * std::sqrt(2.0 * g / L);
    if (T < wash::get_variable("next_report") && t < wash::get_end_time()) return;
    std::printf("front T=%.5f x/L=%.5f\n", T, (wash::get_variable("front") + 0.5 * Spacing()) / L);
    std::fflush(stdout);
    wash::set_variable("next_report", std::floor(T / reportT + 1e-9) * reportT + reportT);
}

int main(int argc, char** argv) {
    int column = argc > 1 ? std::atoi(argv[1]) : defaultColumn;
    if (column < 4) column = defaultColumn;
    double tankWidth = argc > 2 ? std::atof(argv[2]) * L : defaultTankWidth;
    if (!(tankWidth >= L)) tankWidth = defaultTankWidth;
    wash::set_precision("double");
    wash::set_influence_radius(sph::wendland_c2::support * hFactor * L / column);
    wash::set_simulation_name("dam_break_2d");
    wash::add_variable("column", column);
    wash::add_variable("tank_width", tankWidth);
    wash::add_variable("front", 0.0);
    wash::add_variable("next_report", 0.0);
    wash::add_force("pressure", 1);
    wash::add_force("density_rate", 1);
    wash::add_force("wall_vel", 2);
    wash::add_force("time_step", 1);
    wash::add_force("vel_half", 2);
    wash::add_force("density_half", 1);
    wash::add_particle_type("fluid"); // the default type
    wash::add_particle_type("wall");
    wash::add_init_kernel(&Spawn);
    wash::add_reduction_kernel(&TimeStep, wash::Reduction::Min, "time_step", "fluid");
    wash::add_void_kernel(&LastStep);
    wash::add_update_kernel(&KickDrift, "fluid");
    wash::add_force_kernel(&Walls, "wall", "fluid");
    wash::add_force_kernel(&Rates, "fluid");
    wash::add_update_kernel(&Kick, "fluid");
    wash::add_reduction_kernel(&Front, wash::Reduction::Max, "front", "fluid");
    wash::add_void_kernel(&Report);
    wash::set_end_time(endT / std::sqrt(2.0 * g / L));
    wash::start();
    return 0;
}
