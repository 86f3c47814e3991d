//===- wash/detail/progress.hpp - run header, progress line, summary -*- C++ -*-===//
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace wash::detail {

/// Prints a one-line progress report on stderr, redrawn in place, when stderr
/// is a terminal (and not --quiet): step, simulated time, particles/s and the
/// time left (by simulated time when there is an end time, else by steps).
/// Flushes standard output at each update, terminal or not, so that what
/// void kernels print shows while the run goes on.
class Progress {
public:
  Progress(std::uint64_t totalSteps, std::uint64_t particles, bool enabled,
           std::optional<double> endTime = std::nullopt);
  void update(std::uint64_t step, double time = 0.0);
  /// Clears the progress line and flushes standard output; returns the
  /// seconds since construction.
  double finish();

  /// "step 10/100  3.2e+06 particles/s  ETA 4 s": exposed for tests.
  static std::string line(std::uint64_t step, std::uint64_t totalSteps, double particlesPerSecond,
                          double etaSeconds);
  /// With simulated time: "step 10  t = 0.012 of 0.05  3.2e+06 particles/s
  /// ETA 4 s" (the total steps too when there is a step limit, "of" and the
  /// end time only when there is one).
  static std::string timeLine(std::uint64_t step, std::uint64_t totalSteps, double time,
                              std::optional<double> endTime, double particlesPerSecond,
                              double etaSeconds);

private:
  using Clock = std::chrono::steady_clock;
  std::uint64_t totalSteps_, particles_;
  bool enabled_;
  std::optional<double> endTime_;
  Clock::time_point start_, lastDraw_;
};

} // namespace wash::detail
