//===- wash/backend/run.hpp - what a generated program's start() calls -*- C++ -*-===//
//
// The run around the generated kernels: settings and program options, run
// header, frames and dump through the shared writers, progress, and the check
// that every field a kernel wrote is finite.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/box.hpp>
#include <wash/detail/frame.hpp>
#include <wash/detail/options.hpp>
#include <wash/detail/progress.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/detail/run_settings.hpp>
#include <wash/detail/search.hpp>
#include <wash/vec.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace wash::backend {

/// What the simulation's main configured: the store every runtime shares.
using Settings = detail::RunSettings;
/// Generated storage headers set settings().dimensions in a static initialiser.
inline Settings &settings() { return detail::runSettings(); }
using detail::programOptions;

/// Whether every component of a value is finite. The generated particle loops
/// test what each kernel wrote right after it ran, while the values are still
/// in registers; Run::checkFinite then names the culprit, on the rare failure.
inline bool finite(double v) { return std::isfinite(v); }
template <typename T, int D> bool finite(const Vec<T, D> &v) {
  bool all = true;
  for (int a = 0; a < D; ++a)
    all &= bool(std::isfinite(v.at(a)));
  return all;
}

/// What a generated program was translated for: the run checks main's
/// settings against it. Generated code names every member.
struct Translation {
  const char *backend = "serial";
  int dimensions = 2;
  bool floatStorage = false;          ///< set_precision("float")
  bool smoothingLengthSearch = false; ///< set_smoothing_length_support
};

class Run {
public:
  /// Checks the settings against what the program was translated for. Only a
  /// run that `writes` (rank 0 of an MPI job) prints and writes files; every
  /// rank still builds the frames, which may be collective.
  Run(const Translation &translated, bool writes);
  ~Run();

  std::uint64_t steps() const { return steps_; }
  /// The influence radius (fixed-radius rule only).
  double radius() const { return radius_; }
  /// The support radius in units of h (smoothing-length rule only).
  double support() const { return *settings().search.support; }
  const detail::Box &box() const { return settings().box; }

  /// After the init kernels: prints the header, writes frame 0 if due.
  template <typename FrameFn> void begin(std::size_t particles, FrameFn frame) {
    started(particles);
    if (frameDue(0))
      write(0, frame());
    stepStart_ = Clock::now();
  }
  /// After every kernel of a step.
  template <typename FrameFn> void endStep(std::uint64_t step, FrameFn frame) {
    stepSeconds_ += std::chrono::duration<double>(Clock::now() - stepStart_).count();
    if (settings().stopRequested)
      steps_ = step; // wash::stop(): this step is the last, and written as such
    if (frameDue(step))
      write(step, frame());
    if (progress_)
      progress_->update(step);
    stepStart_ = Clock::now();
  }
  void finish(const detail::Frame &finalFrame);
  /// Prints one more line of the end-of-run summary (writing run, not --quiet).
  void report(const std::string &line) const;

  /// Stops the run if a value the kernel wrote, at the given positions (the
  /// real particles, or an MPI rank's own), is not finite; the message names
  /// the first bad one in `rows` order. Runs after the init kernels, and after
  /// a particle loop only when its in-loop test failed: one thread is enough.
  template <typename T>
  void checkFinite(const Column<T> &column, const Column<std::uint64_t> &ids,
                   const std::vector<Index> &rows, std::uint64_t step, const char *kernel,
                   const char *field) const {
    for (Index p : rows)
      if (!finite(column[p]))
        fail(step, kernel, field, ids[p], column[p]);
  }

private:
  void started(std::size_t particles);
  bool frameDue(std::uint64_t step) const;
  void write(std::uint64_t step, const detail::Frame &frame);
  template <typename T> static double firstBad(const T &v) { return double(v); }
  template <typename T, int D> static double firstBad(const Vec<T, D> &v) {
    for (int a = 0; a < D; ++a)
      if (!std::isfinite(v.at(a)))
        return double(v.at(a));
    return 0.0;
  }
  template <typename T>
  [[noreturn]] void fail(std::uint64_t step, const char *kernel, const char *field,
                         std::uint64_t id, const T &value) const {
    failWith(step, kernel, field, id, firstBad(value));
  }
  [[noreturn]] void failWith(std::uint64_t step, const char *kernel, const char *field,
                             std::uint64_t id, double value) const;

  std::string backend_;
  int dimensions_;
  bool useFloat_, writes_;
  std::uint64_t steps_ = 0;
  double radius_ = 0.0;
  std::unique_ptr<detail::RunOutput> output_;
  std::unique_ptr<detail::Progress> progress_;
  // The steps' own time, frames written excluded: what the summary reports
  // per particle-step (benchmarks read it; start-up and output vary a lot).
  using Clock = std::chrono::steady_clock;
  Clock::time_point stepStart_;
  double stepSeconds_ = 0.0;
};

} // namespace wash::backend
