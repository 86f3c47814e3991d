#include <wash/detail/progress.hpp>
#include <wash/detail/sim_time.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <unistd.h>

namespace wash::detail {

namespace {
constexpr std::uint64_t noStepLimit = std::numeric_limits<std::uint64_t>::max();
}

Progress::Progress(std::uint64_t totalSteps, std::uint64_t particles, bool enabled,
                   std::optional<double> endTime)
    : totalSteps_(totalSteps), particles_(particles), enabled_(enabled && isatty(STDERR_FILENO)),
      endTime_(endTime), start_(Clock::now()), lastDraw_(start_) {}

std::string Progress::line(std::uint64_t step, std::uint64_t totalSteps, double particlesPerSecond,
                           double etaSeconds) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "step %llu/%llu  %.3g particles/s  ETA %.0f s",
                static_cast<unsigned long long>(step), static_cast<unsigned long long>(totalSteps),
                particlesPerSecond, etaSeconds);
  return buf;
}

std::string Progress::timeLine(std::uint64_t step, std::uint64_t totalSteps, double time,
                               std::optional<double> endTime, double particlesPerSecond,
                               double etaSeconds) {
  char steps[64], clock[96], rest[96];
  if (totalSteps == noStepLimit)
    std::snprintf(steps, sizeof steps, "step %llu", static_cast<unsigned long long>(step));
  else
    std::snprintf(steps, sizeof steps, "step %llu/%llu", static_cast<unsigned long long>(step),
                  static_cast<unsigned long long>(totalSteps));
  if (endTime)
    std::snprintf(clock, sizeof clock, "t = %.6g of %.6g", time, *endTime);
  else
    std::snprintf(clock, sizeof clock, "t = %.6g", time);
  std::snprintf(rest, sizeof rest, "%.3g particles/s  ETA %.0f s", particlesPerSecond, etaSeconds);
  return std::string(steps) + "  " + clock + "  " + rest;
}

void Progress::update(std::uint64_t step, double time) {
  if (step == 0)
    return;
  auto now = Clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(250))
    return;
  lastDraw_ = now;
  std::fflush(stdout);
  if (!enabled_)
    return;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double rate = elapsed > 0 ? double(particles_) * double(step) / elapsed : 0.0;
  double byTime = endTime_ && time > 0.0 ? elapsed / time * (*endTime_ - time) : -1.0;
  double bySteps =
      totalSteps_ == noStepLimit ? -1.0 : elapsed / double(step) * double(totalSteps_ - step);
  // The run ends at whichever limit comes first.
  double eta = byTime < 0.0 ? bySteps : bySteps < 0.0 ? byTime : std::min(byTime, bySteps);
  if (eta < 0.0)
    eta = 0.0;
  const std::string text = endTime_ || simTime().stepSet
                               ? timeLine(step, totalSteps_, time, endTime_, rate, eta)
                               : line(step, totalSteps_, rate, eta);
  std::fprintf(stderr, "\r%s\033[K", text.c_str());
  std::fflush(stderr);
}

double Progress::finish() {
  if (enabled_)
    std::fprintf(stderr, "\r\033[K");
  std::fflush(stdout);
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

} // namespace wash::detail
