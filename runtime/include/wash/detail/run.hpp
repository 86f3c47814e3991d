//===- wash/detail/run.hpp - the run around the kernels, for every runtime -*- C++ -*-===//
//
// What every runtime's start() does besides running kernels: the start-up
// checks of main's settings, the run header, frames and dump through the shared
// writers, progress, the finiteness checks and the end-of-run summary. The
// reference runtime and generated programs both use it, so they check, print
// and write alike.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/checkpoint.hpp>
#include <wash/detail/frame.hpp>
#include <wash/detail/profile.hpp>
#include <wash/detail/progress.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/detail/run_settings.hpp>
#include <wash/detail/sim_time.hpp>
#include <wash/vec.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace wash::detail {

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

/// What a program was translated for: the run checks main's settings against
/// it. Generated code names every member. The reference runtime is not
/// translated: it leaves the precision and the rule unset, and runs whatever
/// main asks for.
struct Translation {
  const char *backend = "serial";
  int dimensions = 2;
  std::optional<bool> floatStorage = false;          ///< set_precision("float")
  std::optional<bool> smoothingLengthSearch = false; ///< set_smoothing_length_support
  std::optional<bool> symmetricSupport = false;      ///< ... with Support::Symmetric
  /// What a checkpoint must have been written by: a hash of the kernels and
  /// columns (the reference's is made from its kernels and forces).
  std::string program = "";
};

/// Whether steps that took `cpuSeconds` of CPU on `threads` threads in
/// `wallSeconds`, preempted `preemptions` times, shared their cores with other
/// processes: the summary then warns that its times are not the program's.
bool coresWereBusy(double cpuSeconds, double wallSeconds, int threads, long preemptions);

/// How many multiples of `every` (a positive time option, named `option`)
/// `time` holds; refused past 2^53, where they are no longer distinct.
std::uint64_t multiplesIn(double time, double every, const char *option);

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
  double support() const { return *runSettings().search.support; }
  const Box &box() const { return runSettings().box; }

  /// After the init kernels: prints the header, checks that there is room for
  /// a frame where the run writes (before any step), writes frame 0 if due.
  /// Every rank builds the frame (it may be collective).
  template <typename FrameFn> void begin(std::size_t particles, FrameFn frame) {
    started(particles);
    runStage() = {particles, 0, true, steps_};
    const Frame first = built(frame);
    reserve(first);
    if (frameDue(0) || outputTimeCrossed())
      write(0, first);
    if (programOptions().checkpointDt) // multiples after the start time
      nextCheckpoint_ =
          multiplesIn(simTime().time, *programOptions().checkpointDt, "--checkpoint-dt") + 1;
    runStage().step = 1;
    watchStopSignals();
    startStepClocks();
  }
  /// Where a kernel's time begins (--profile; one branch when off).
  void kernel(const char *name) const { profileMark(name); }
  /// After every kernel of a step.
  /// Advances the simulated time by the time step; the step is the last when
  /// wash::stop() was called or the time reached the end time.
  template <typename FrameFn> void endStep(std::uint64_t step, FrameFn frame) {
    stepSeconds_ += std::chrono::duration<double>(Clock::now() - stepStart_).count();
    stepCpuSeconds_ += processCpuSeconds() - stepCpuStart_;
    profileMark("(end of step: time, progress)");
    const bool timeFrame = advanceTime(step);
    if (runSettings().stopRequested || endTimeReached())
      runStage().steps = steps_ = step; // this step is the last, and written as such
    noteCheckpoint(step);
    if (frameDue(step) || timeFrame) {
      write(step, built(frame));
      // A frame written only because the step is the last is no frame of a
      // longer run: a checkpoint leaves it out of the series.
      const std::uint64_t every = programOptions().outputEvery;
      lastOnlyFrame_ = timeFrame || (every && step % every == 0) ? 0 : step;
    }
    if (progress_)
      progress_->update(step, simTime().time);
    runStage().step = step + 1;
    stepStart_ = Clock::now();
    stepCpuStart_ = processCpuSeconds();
  }
  void finish(const Frame &finalFrame);

  // Checkpoint and restart (wash/detail/checkpoint.hpp; the backends' and the
  // reference's start() write and read the particles).
  bool restarting() const { return !programOptions().restartPath.empty(); }
  /// The first step of the loop: 1, or the one after a checkpoint's.
  std::uint64_t firstStep() const { return firstStep_; }
  /// This program's identity, with the columns it stores.
  CheckpointIdentity identity(std::vector<CheckpointField> fields) const;
  /// Instead of begin(), after the particles were read from `folder`: the
  /// state of `saved` restored, the header printed. Returns the first step.
  std::uint64_t resume(const CheckpointState &saved, std::size_t particles,
                       const std::string &folder, double readSeconds);
  /// Whether --checkpoint-every or --checkpoint-dt asks for one after the
  /// step endStep just ended.
  bool checkpointDue() const { return checkpointDue_; }
  /// Where checkpoints go: --checkpoint-dir, else <out>/checkpoints.
  std::string checkpointDir() const;
  /// The state after `step`, for the index (on the writing process).
  CheckpointState checkpointState(std::uint64_t step, std::uint32_t shards,
                                  std::uint64_t particles) const;
  /// The run stops after a signal's checkpoint: its series closed as far as
  /// it got (RunOutput::closeSeries). Collective under MPI.
  void stopped() {
    if (output_)
      output_->closeSeries();
  }
  /// Says where the checkpoint went and how long it took (writing run, not
  /// --quiet); that time is not counted as the steps'.
  void checkpointWritten(const std::string &folder, std::uint64_t step, double seconds);
  /// Prints one more line of the end-of-run summary (writing run, not --quiet).
  void report(const std::string &line) const;

  /// Stops the run if a value the kernel wrote, at the given positions (the
  /// real particles, or an MPI rank's own), is not finite; the message names
  /// the first bad one in `rows` order. Runs after the init kernels, and after
  /// a particle loop only when its in-loop test failed: one thread is enough.
  template <typename T, typename Row>
  void checkFinite(const std::vector<T> &column, const std::vector<std::uint64_t> &ids,
                   const std::vector<Row> &rows, std::uint64_t step, const char *kernel,
                   const char *field) const {
    for (Row p : rows)
      if (!finite(column[p]))
        fail(step, kernel, field, ids[p], column[p]);
  }
  /// The same over a whole frame (the reference checks all of its state).
  void checkFinite(const Frame &frame, std::uint64_t step, const std::string &kernel) const;

private:
  /// frame(), with an out-of-memory error that says what was being built.
  template <typename FrameFn> static Frame built(FrameFn frame) {
    try {
      return frame();
    } catch (const std::bad_alloc &) {
      throw RunError("out of memory building an output frame of " +
                     std::to_string(runStage().particles) + " particles (" + runStage().describe() +
                     ")");
    }
  }
  void started(std::size_t particles);
  /// The steps' clocks (and --profile's) start now.
  void startStepClocks();
  /// The summary's CPU line and, where the steps got much less CPU than they
  /// waited for, the warning.
  void reportCpu() const;
  /// Adds the time step to the time (after checking it); whether a frame is
  /// due by --output-dt.
  bool advanceTime(std::uint64_t step);
  /// Whether the time crossed the next multiple of --output-dt (then moved on).
  bool outputTimeCrossed();
  bool endTimeReached() const { return endTime_ && simTime().time >= *endTime_; }
  bool frameDue(std::uint64_t step) const;
  void noteCheckpoint(std::uint64_t step);
  void reserve(const Frame &frame);
  void write(std::uint64_t step, const Frame &frame);
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

  std::string backend_, program_;
  int dimensions_;
  bool useFloat_, writes_;
  std::uint64_t steps_ = 0;
  double radius_ = 0.0;
  std::optional<double> endTime_, outputDt_;
  std::uint64_t nextOutput_ = 0;     ///< the multiple of outputDt_ the next time frame waits for
  std::uint64_t nextCheckpoint_ = 0; ///< the same for --checkpoint-dt
  std::uint64_t stuckSteps_ = 0;     ///< steps in a row that left the time where it was
  bool checkpointDue_ = false;
  std::uint64_t firstStep_ = 1;
  std::uint64_t lastOnlyFrame_ = 0; ///< a step whose frame was written only as the last
  std::unique_ptr<RunOutput> output_;
  std::unique_ptr<Progress> progress_;
  // The steps' own time, frames written excluded: what the summary reports
  // per particle-step (benchmarks read it; start-up and output vary a lot).
  using Clock = std::chrono::steady_clock;
  Clock::time_point stepStart_;
  double stepSeconds_ = 0.0;
  // The same in CPU time of the whole process (every thread), and the
  // involuntary context switches of the steps: other processes taking the
  // cores away.
  double stepCpuStart_ = 0.0, stepCpuSeconds_ = 0.0;
  long involuntarySwitchesAtStart_ = 0;
};

} // namespace wash::detail
