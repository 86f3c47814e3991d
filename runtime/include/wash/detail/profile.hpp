//===- wash/detail/profile.hpp - where the steps' time goes (--profile) -*- C++ -*-===//
//
// With --profile the run times each phase of its steps: every kernel (the
// generated driver, and the reference, mark where each begins), the neighbour
// search, MPI halo exchanges and migration, output and checkpoints (scopes
// nested in whatever phase they interrupt, their time taken out of it). Time
// from one mark to the next is the marked phase's, so the phases add up to the
// steps' wall time. Off, a mark or a scope costs one branch.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wash::detail {

/// Set from --profile before the run starts.
inline bool profiling = false;

/// The threads a particle loop runs on in this process (the OpenMP loops set
/// it): what the summary weighs the CPU time against.
inline int loopThreads = 1;

/// One phase's totals.
struct ProfiledPhase {
  std::string name;
  std::uint64_t calls = 0;
  double wallSeconds = 0.0, cpuSeconds = 0.0;
};

/// From now on, time goes to `phase` (a kernel's name).
void profileMarkSlow(const char *phase);
inline void profileMark(const char *phase) {
  if (profiling)
    profileMarkSlow(phase);
}

/// The time of its lifetime goes to `phase`, then back to the phase it interrupted.
class ProfileScope {
public:
  explicit ProfileScope(const char *phase) {
    if (profiling)
      interrupted_ = enter(phase);
  }
  ~ProfileScope() {
    if (interrupted_)
      leave(interrupted_);
  }
  ProfileScope(const ProfileScope &) = delete;
  ProfileScope &operator=(const ProfileScope &) = delete;

private:
  /// The interrupted phase's number, plus 1 (0: not profiling).
  static std::size_t enter(const char *phase);
  static void leave(std::size_t interrupted);
  std::size_t interrupted_ = 0;
};

/// The phases so far, in the order they first ran (the time up to now
/// included); profileReset starts afresh at `phase`.
std::vector<ProfiledPhase> profiledPhases();
void profileReset(const char *phase);

/// The table --profile prints: one row per phase, then the total.
std::string profileTable(const std::vector<ProfiledPhase> &phases, std::uint64_t steps,
                         double particleSteps, const std::string &whose);

/// This process's CPU time (every thread's), in seconds.
double processCpuSeconds();

} // namespace wash::detail
