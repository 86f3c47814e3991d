// --profile (wash/detail/profile.hpp).
#include <wash/detail/profile.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace wash::detail {
namespace {

struct Clocks {
  double wall = 0.0, cpu = 0.0;
  static Clocks now() {
    return {
        std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(),
        processCpuSeconds()};
  }
};

struct Profiler {
  std::vector<ProfiledPhase> phases;
  std::size_t current = 0;
  Clocks since;

  std::size_t indexOf(const char *name) {
    for (std::size_t k = 0; k < phases.size(); ++k)
      if (phases[k].name == name)
        return k;
    phases.push_back({name});
    return phases.size() - 1;
  }
  /// The first phase, from now.
  void start(const char *name) {
    current = indexOf(name);
    phases[current].calls = 1;
    since = Clocks::now();
  }
  /// The time since the last switch goes to the current phase; `next` is next.
  void switchTo(std::size_t next, bool newCall) {
    const Clocks now = Clocks::now();
    if (!phases.empty()) {
      phases[current].wallSeconds += now.wall - since.wall;
      phases[current].cpuSeconds += now.cpu - since.cpu;
    }
    current = next;
    phases[current].calls += newCall;
    since = now;
  }
};

Profiler &profiler() {
  static Profiler p;
  return p;
}

} // namespace

double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void profileMarkSlow(const char *phase) {
  Profiler &p = profiler();
  p.switchTo(p.indexOf(phase), true);
}

std::size_t ProfileScope::enter(const char *phase) {
  Profiler &p = profiler();
  if (p.phases.empty()) // before the steps: a phase of its own
    p.start("(before the steps)");
  const std::size_t interrupted = p.current;
  p.switchTo(p.indexOf(phase), true);
  return interrupted + 1;
}

void ProfileScope::leave(std::size_t interrupted) { profiler().switchTo(interrupted - 1, false); }

std::vector<ProfiledPhase> profiledPhases() {
  Profiler &p = profiler();
  if (!p.phases.empty())
    p.switchTo(p.current, false);
  return p.phases;
}

void profileReset(const char *phase) {
  profiler() = Profiler{};
  profiler().start(phase);
}

std::string profileTable(const std::vector<ProfiledPhase> &phases, std::uint64_t steps,
                         double particleSteps, const std::string &whose) {
  double wall = 0.0, cpu = 0.0;
  std::size_t width = 5;
  for (const ProfiledPhase &p : phases) {
    wall += p.wallSeconds, cpu += p.cpuSeconds;
    width = std::max(width, p.name.size());
  }
  const double perStep = steps ? 1.0 / double(steps) : 0.0;
  std::string table = "wash: profile of " + std::to_string(steps) + " steps (" + whose + ")\n";
  char line[512];
  std::snprintf(line, sizeof line, "  %-*s %9s %10s %10s %7s %12s %10s\n", int(width), "phase",
                "calls", "wall s", "ms/step", "% wall", "ns/particle", "CPU s");
  table += line;
  auto row = [&](const std::string &name, std::uint64_t calls, double w, double c) {
    std::snprintf(line, sizeof line, "  %-*s %9llu %10.4f %10.4f %6.1f%% %12.2f %10.4f\n",
                  int(width), name.c_str(), (unsigned long long)calls, w, w * perStep * 1e3,
                  wall > 0 ? 100.0 * w / wall : 0.0,
                  particleSteps > 0 ? w * 1e9 / particleSteps : 0.0, c);
    table += line;
  };
  std::uint64_t calls = 0;
  for (const ProfiledPhase &p : phases) {
    row(p.name, p.calls, p.wallSeconds, p.cpuSeconds);
    calls += p.calls;
  }
  row("total", calls, wall, cpu);
  return table;
}

} // namespace wash::detail
