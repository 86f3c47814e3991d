// wash/settings.hpp's simulated time: the same in the reference and every backend.
#include <wash/detail/run_settings.hpp>
#include <wash/detail/sim_time.hpp>
#include <wash/detail/variables.hpp>
#include <wash/settings.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

namespace wash {
namespace detail {

SimTime &simTime() {
  static SimTime t;
  return t;
}

std::string checkTimeStep(double dt) {
  if (std::isfinite(dt) && dt >= 0.0)
    return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", dt);
  return std::string("the time step is ") + text + "; it must be finite and not negative";
}

void setReducedTimeStep(double dt) {
  simTime().step = dt;
  simTime().stepSet = true;
}

} // namespace detail

double get_time() { return detail::simTime().time; }
double get_time_step() { return detail::simTime().step; }

void set_time_step(double dt, CallSite loc) {
  if (std::string bad = detail::checkTimeStep(dt); !bad.empty())
    detail::usageErrorAt(loc, "wash::set_time_step: " + bad);
  detail::setReducedTimeStep(dt);
}

void set_end_time(double time, CallSite loc) {
  if (!std::isfinite(time) || time < 0.0)
    detail::usageErrorAt(loc, "the end time must be a finite number, not negative");
  detail::simTime().endTime = time;
}

double get_end_time() {
  if (const auto &option = detail::programOptions().endTime)
    return *option;
  return detail::simTime().endTime.value_or(std::numeric_limits<double>::infinity());
}

} // namespace wash
