#include <wash/detail/progress.hpp>

#include <cstdio>
#include <unistd.h>

namespace wash::detail {

Progress::Progress(std::uint64_t totalSteps, std::uint64_t particles, bool enabled)
    : totalSteps_(totalSteps), particles_(particles), enabled_(enabled && isatty(STDERR_FILENO)),
      start_(Clock::now()), lastDraw_(start_) {}

std::string Progress::line(std::uint64_t step, std::uint64_t totalSteps, double particlesPerSecond,
                           double etaSeconds) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "step %llu/%llu  %.3g particles/s  ETA %.0f s",
                static_cast<unsigned long long>(step), static_cast<unsigned long long>(totalSteps),
                particlesPerSecond, etaSeconds);
  return buf;
}

void Progress::update(std::uint64_t step) {
  if (!enabled_ || step == 0)
    return;
  auto now = Clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(250))
    return;
  lastDraw_ = now;
  double elapsed = std::chrono::duration<double>(now - start_).count();
  double rate = elapsed > 0 ? double(particles_) * double(step) / elapsed : 0.0;
  double eta = elapsed / double(step) * double(totalSteps_ - step);
  std::fprintf(stderr, "\r%s\033[K", line(step, totalSteps_, rate, eta).c_str());
  std::fflush(stderr);
}

double Progress::finish() {
  if (enabled_)
    std::fprintf(stderr, "\r\033[K");
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

} // namespace wash::detail
