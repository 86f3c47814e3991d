// A 2D scene for the simulated time: the time step comes from a Min reduction
// into "time_step" and changes every step, a void kernel shortens the last
// step to the end time, and every particle records the time it was given.
//
//   sim_time [stop_time] [slow]
// stop_time: a void kernel calls wash::stop() once the time reaches it (to
// check that stop() still ends a run with an end time); slow: each step
// sleeps 2 ms and the first one prints a line (standard output flushing).
#include <wash/wash.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

constexpr int side = 8;

void spawn() {
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      const double x = (i + 0.5) / side, y = (j + 0.5) / side;
      wash::create_particle(1.0, 1.0, 0.1, wash::Vec2D(x, y),
                            wash::Vec2D(0.3 * std::sin(6.0 * y), 0.2 * std::cos(5.0 * x)));
    }
}

void spread(wash::Particle &p, const std::vector<wash::Particle> &neighbours) {
  wash::Vec2D acc(0.0, 0.0);
  for (const wash::Particle &q : neighbours)
    acc += (p.get_pos() - q.get_pos()) * 0.05;
  p.set_acc(acc);
}

// An irregular time step: it depends on the speeds, which change every step.
double stableStep(const wash::Particle &p) { return 0.013 / (1.0 + 3.0 * p.get_vel().magnitude()); }

void lastStep() {
  wash::set_time_step(std::min(wash::get_time_step(), wash::get_end_time() - wash::get_time()));
  if (wash::get_time() >= wash::get_variable("stop_time"))
    wash::stop();
  if (wash::get_variable("slow") != 0.0) {
    if (wash::get_time() == 0.0)
      std::printf("first step done\n");
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void move(wash::Particle &p) {
  const double dt = wash::get_time_step();
  p.set_vel(p.get_vel() + p.get_acc() * dt);
  p.set_pos(p.get_pos() + p.get_vel() * dt);
  // The time at the end of this iteration, as the runtime will compute it.
  p.set_force_scalar("start", wash::get_time());
  p.set_force_scalar("time", wash::get_time() + dt);
  p.set_force_scalar("dt", dt);
}

int main(int argc, char **argv) {
  wash::set_precision("double");
  wash::set_influence_radius(0.3);
  wash::set_bounding_box({0.0, 0.0}, {1.0, 1.0}, {true, true});
  wash::set_simulation_name("sim_time");
  wash::add_variable("stop_time", argc > 1 ? std::atof(argv[1]) : INFINITY);
  wash::add_variable("slow", argc > 2 && std::strcmp(argv[2], "slow") == 0 ? 1.0 : 0.0);
  wash::add_force("start", 1);
  wash::add_force("time", 1);
  wash::add_force("dt", 1);
  wash::add_init_kernel(&spawn);
  wash::add_force_kernel(&spread);
  wash::add_reduction_kernel(&stableStep, wash::Reduction::Min, "time_step");
  wash::add_void_kernel(&lastStep);
  wash::add_update_kernel(&move);
  wash::set_end_time(1.0);
  wash::start();
}
