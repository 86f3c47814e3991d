//===- wash/detail/progress.hpp - run header, progress line, summary -*- C++ -*-===//
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace wash::detail {

/// Prints a one-line progress report on stderr, redrawn in place, when stderr
/// is a terminal (and not --quiet): step, particles/s and the time left.
class Progress {
public:
  Progress(std::uint64_t totalSteps, std::uint64_t particles, bool enabled);
  void update(std::uint64_t step);
  /// Clears the progress line; returns the seconds since construction.
  double finish();

  /// "step 10/100  3.2e+06 particles/s  ETA 4 s": exposed for tests.
  static std::string line(std::uint64_t step, std::uint64_t totalSteps, double particlesPerSecond,
                          double etaSeconds);

private:
  using Clock = std::chrono::steady_clock;
  std::uint64_t totalSteps_, particles_;
  bool enabled_;
  Clock::time_point start_, lastDraw_;
};

} // namespace wash::detail
