// adaptive_h under the symmetric rule (wash::Support::Symmetric): j is a
// neighbour of i within 2 max(h_i, h_j). The smoothing lengths differ by a
// factor of up to three across the box, so many pairs are found only through
// the neighbour's h_j; the density and the force use both particles' kernels,
// and the neighbour count (the list's length) steers h, so a pair missed or
// listed wrongly changes the dump. Every particle has its own h, adapted each
// step, so the search changes between the two force kernels of a step; x and
// y are periodic, z is closed by walls; the time step comes from a Min
// reduction and a void kernel ends the run with wash::stop() at an end time.
#include <wash/wash.hpp>

#include <algorithm>
#include <cmath>

constexpr int cells = 10;
constexpr double spacing = 1.0 / cells;
constexpr double soundSpeed = 1.0;
constexpr double targetNeighbours = 30.0;
constexpr double hMin = 0.05, hMax = 0.2; // 2 hMax < half the periodic box
constexpr double endTime = 2.0;

// Cubic spline with support 2h, 3D normalisation.
double kernelW(double r, double h) {
  const double q = r / h, sigma = 1.0 / (PI * h * h * h);
  if (q < 1.0)
    return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  if (q < 2.0)
    return sigma * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}

double kernelGradient(double r, double h) {
  const double q = r / h, sigma = 1.0 / (PI * h * h * h * h);
  if (q < 1.0)
    return sigma * (-3.0 * q + 2.25 * q * q);
  if (q < 2.0)
    return sigma * -0.75 * (2.0 - q) * (2.0 - q);
  return 0.0;
}

void spawn() {
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j)
      for (int k = 0; k < cells; ++k) {
        const double x = (i + 0.5) * spacing, y = (j + 0.5) * spacing,
                     z = (k + 0.5) * spacing + 0.01 * std::sin(7.0 * x + 3.0 * y);
        const double h = 0.11 + 0.06 * std::sin(2.0 * PI * x); // 0.05 to 0.17
        wash::create_particle(1.0, spacing * spacing * spacing, h, wash::Vec3D(x, y, z),
                              wash::Vec3D(0.1 * std::sin(2.0 * PI * y), 0.0, 0.0));
      }
}

void density(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  const double hi = p.get_smoothing_length();
  double rho = p.get_mass() * kernelW(0.0, hi);
  for (const wash::Particle &q : neighbours) {
    const double r = (p.get_pos() - q.get_pos()).magnitude();
    rho += q.get_mass() * 0.5 * (kernelW(r, hi) + kernelW(r, q.get_smoothing_length()));
  }
  p.set_density(rho);
  p.set_force_scalar("pressure", soundSpeed * soundSpeed * (rho - 1.0));
  p.set_force_scalar("neighbours", double(neighbours.size()));
}

void adaptSmoothingLength(wash::Particle &p) {
  const double n = p.get_force_scalar("neighbours") + 1.0;
  const double h = p.get_smoothing_length() * 0.5 * (1.0 + std::cbrt(targetNeighbours / n));
  p.set_smoothing_length(std::clamp(h, hMin, hMax));
}

void pressureForce(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  wash::Vec3D acc(0.0, 0.0, -0.5);
  const double pi = p.get_force_scalar("pressure") / (p.get_density() * p.get_density());
  for (const wash::Particle &q : neighbours) {
    const wash::Vec3D d = p.get_pos() - q.get_pos();
    const double r = d.magnitude();
    if (r == 0.0)
      continue;
    const double pj = q.get_force_scalar("pressure") / (q.get_density() * q.get_density());
    const double gradient = 0.5 * (kernelGradient(r, p.get_smoothing_length()) +
                                   kernelGradient(r, q.get_smoothing_length()));
    acc -= d / r * (q.get_mass() * (pi + pj) * gradient);
  }
  p.set_acc(acc);
}

double stableStep(const wash::Particle &p) {
  return 0.25 * p.get_smoothing_length() / (soundSpeed + p.get_vel().magnitude());
}

void move(wash::Particle &p) {
  const double dt = wash::get_variable("dt");
  wash::Vec3D v = p.get_vel() + p.get_acc() * dt;
  wash::Vec3D x = p.get_pos() + v * dt;
  if (x.at(2) < 0.0 || x.at(2) > 1.0) { // walls at z = 0 and 1
    *v[2] = -*v[2];
    *x[2] = x.at(2) < 0.0 ? -x.at(2) : 2.0 - x.at(2);
  }
  p.set_vel(v);
  p.set_pos(x);
}

void advanceTime() {
  wash::set_variable("time", wash::get_variable("time") + wash::get_variable("dt"));
  if (wash::get_variable("time") >= endTime)
    wash::stop();
}

int main() {
  wash::set_precision("double");
  wash::set_smoothing_length_support(2.0, wash::Support::Symmetric);
  wash::set_bounding_box({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}, {true, true, false});
  wash::set_simulation_name("symmetric_h");
  wash::set_max_iterations(100000); // the end time stops it first
  wash::add_variable("dt", 0.0);
  wash::add_variable("time", 0.0);
  wash::add_force("pressure", 1);
  wash::add_force("neighbours", 1);
  wash::add_init_kernel(&spawn);
  wash::add_force_kernel(&density);
  wash::add_update_kernel(&adaptSmoothingLength);
  wash::add_force_kernel(&pressureForce);
  wash::add_reduction_kernel(&stableStep, wash::Reduction::Min, "dt");
  wash::add_update_kernel(&move);
  wash::add_void_kernel(&advanceTime);
  wash::start();
}
