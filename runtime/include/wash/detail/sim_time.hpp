//===- wash/detail/sim_time.hpp - the simulated time of a run ----*- C++ -*-===//
//
// The one clock behind wash::get_time / get_time_step / set_time_step, shared
// by the reference runtime and every backend. Every process of an MPI run
// keeps its own copy; they agree, as only code every process runs the same
// way (main, init and void kernels, reductions) sets the time step.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace wash::detail {

struct SimTime {
  double time = 0.0;
  double step = 0.0;
  bool stepSet = false;          ///< set_time_step or a reduction ever ran
  std::optional<double> endTime; ///< set_end_time (the option overrides it)
};
SimTime &simTime();

/// What a reduction kernel targeting "time_step" stores (checked when the
/// runtime advances the time, at the end of the iteration).
void setReducedTimeStep(double dt);

/// The reserved reduction target that is the time step, not a variable.
inline constexpr const char *timeStepTarget = "time_step";

/// Why `dt` cannot be a time step, or "".
std::string checkTimeStep(double dt);

} // namespace wash::detail
