#include <wash/detail/processes.hpp>
#include <wash/detail/run.hpp>

#include <wash/detail/variables.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include <sys/resource.h>

namespace wash::detail {
namespace {

/// The precision the run stores: what it was translated for, else main's.
bool checkedPrecision(const Translation &translated, const RunSettings &s) {
  if (!translated.floatStorage)
    return s.useFloat.value_or(false);
  const bool translatedForFloat = *translated.floatStorage;
  if (s.useFloat && *s.useFloat != translatedForFloat)
    throw RunError(std::string("this program was translated for ") +
                   (translatedForFloat ? "float" : "double") + " precision, but main asked for " +
                   (*s.useFloat ? "float" : "double") +
                   "; call set_precision unconditionally in main");
  // The reference stores doubles unless main asks: a float translation of a
  // main that skipped its set_precision call this run would differ from it.
  if (!s.useFloat && translatedForFloat)
    throw RunError("this program was translated for float precision, but main did not call "
                   "set_precision(\"float\") in this run; call set_precision unconditionally "
                   "in main");
  return translatedForFloat;
}

void checkRule(const Translation &translated, const SearchRule &rule) {
  if (std::string bad = rule.check(); !bad.empty())
    throw RunError(bad);
  if (!translated.smoothingLengthSearch)
    return;
  const bool translatedForSupport = *translated.smoothingLengthSearch;
  if (rule.perParticle() != translatedForSupport)
    throw RunError(std::string("this program was translated for ") +
                   (translatedForSupport ? "a smoothing-length" : "an influence-radius") +
                   " neighbour search, but main asked for " +
                   (translatedForSupport ? "an influence radius" : "smoothing lengths") +
                   "; call the neighbour-rule setting unconditionally in main");
  if (translatedForSupport && translated.symmetricSupport &&
      rule.symmetric != *translated.symmetricSupport)
    throw RunError(std::string("this program was translated for the ") +
                   (*translated.symmetricSupport ? "symmetric" : "gather") +
                   " support rule, but main asked for wash::Support::" +
                   (rule.symmetric ? "Symmetric" : "Gather") +
                   "; call the neighbour-rule setting unconditionally in main");
}

std::string decimal(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

} // namespace

std::uint64_t multiplesIn(double time, double every, const char *option) {
  const double multiples = std::floor(time / every);
  // Past 2^53 neighbouring multiples are the same double: no frame or
  // checkpoint time could be told from the next (and the count would not fit).
  if (!(multiples < 0x1p53))
    throw RunError("the simulated time t = " + decimal(time) + " is " + decimal(multiples) +
                   " multiples of " + option + " " + decimal(every) +
                   ", more than 2^53: no two of them can be told apart; give " + option +
                   " a larger value");
  return std::uint64_t(multiples);
}

namespace {

/// Whether `time` reached the multiple `next` of `every` (then moves `next`
/// beyond it: a long step may cross several, and counts once).
bool crossed(double time, double every, std::uint64_t &next, const char *option) {
  if (time < double(next) * every)
    return false;
  next = std::max(next, multiplesIn(time, every, option));
  while (double(next) * every <= time)
    ++next;
  return true;
}

std::string afterKernel(std::uint64_t step, const std::string &kernel) {
  return "step " + std::to_string(step) + ": after kernel '" + kernel + "': ";
}

} // namespace

Run::Run(const Translation &translated, bool writes)
    : backend_(translated.backend), program_(identityHash(translated.program)),
      dimensions_(translated.dimensions), useFloat_(checkedPrecision(translated, runSettings())),
      writes_(writes) {
  const RunSettings &s = runSettings();
  const RunOptions &o = programOptions();
  checkRule(translated, s.search);
  endTime_ = o.endTime ? o.endTime : simTime().endTime;
  outputDt_ = o.outputDt;
  if (!o.steps && !s.maxIterations && !endTime_)
    throw RunError("no iteration count: call wash::set_max_iterations or pass --steps N (or "
                   "give an end time: wash::set_end_time or --end-time T)");
  steps_ = o.steps           ? *o.steps
           : s.maxIterations ? *s.maxIterations
                             : std::numeric_limits<std::uint64_t>::max(); // until the end time
  radius_ = s.search.radius.value_or(0.0);
  if (std::string bad = checkBox(s.box, dimensions_, radius_); !bad.empty())
    throw RunError(bad);
  // In a distributed run every process takes part in writing (rank 0 only
  // creates and checks the output directory).
  if (writes_ || processes())
    output_ = std::make_unique<RunOutput>(o, s.outputBaseName());
}

Run::~Run() = default;

bool Run::advanceTime(std::uint64_t step) {
  SimTime &t = simTime();
  if (std::string bad = checkTimeStep(t.step); !bad.empty())
    throw RunError("at the end of step " + std::to_string(step) + ": " + bad);
  const double before = t.time;
  t.time += t.step;
  stuckSteps_ = t.time == before ? stuckSteps_ + 1 : 0;
  // A run bounded only by its end time would never end: at once if nothing
  // ever set a time step, else after a while (a step computed by a reduction
  // may be 0 in the first steps: Sedov's is at step 1).
  constexpr std::uint64_t stuckLimit = 100;
  if (stuckSteps_ && (!t.stepSet || stuckSteps_ >= stuckLimit) && endTime_ &&
      steps_ == std::numeric_limits<std::uint64_t>::max() && !runSettings().stopRequested &&
      !endTimeReached())
    throw RunError(
        "at the end of step " + std::to_string(step) + ": the simulated time did " + "not advance" +
        (t.stepSet ? " in " + std::to_string(stuckSteps_) + " steps" : std::string()) +
        " (t = " + decimal(t.time) + ", time step " + decimal(t.step) +
        (t.stepSet ? "" : ", never set") + ") and the run ends only at t = " + decimal(*endTime_) +
        ": it would never end; set a time step that advances " +
        "the time (wash::set_time_step, or a reduction into \"time_step\") or " +
        "give an iteration count (--steps N or wash::set_max_iterations)");
  return outputTimeCrossed();
}

bool Run::outputTimeCrossed() {
  return outputDt_ && crossed(simTime().time, *outputDt_, nextOutput_, "--output-dt");
}

void Run::noteCheckpoint(std::uint64_t step) {
  const RunOptions &o = programOptions();
  const bool byTime = o.checkpointDt &&
                      crossed(simTime().time, *o.checkpointDt, nextCheckpoint_, "--checkpoint-dt");
  checkpointDue_ = byTime || (o.checkpointEvery && step % o.checkpointEvery == 0);
}

CheckpointIdentity Run::identity(std::vector<CheckpointField> fields) const {
  return {runSettings().simulationName,
          program_,
          std::uint32_t(dimensions_),
          useFloat_,
          std::move(fields),
          backend_ == "reference" ? CheckpointWriter::Reference : CheckpointWriter::Translated};
}

std::string Run::checkpointDir() const { return checkpointDirectory(programOptions()); }

CheckpointState Run::checkpointState(std::uint64_t step, std::uint32_t shards,
                                     std::uint64_t particles) const {
  CheckpointState s;
  s.iteration = step;
  s.time = simTime().time;
  s.timeStep = simTime().step;
  s.timeStepSet = simTime().stepSet;
  s.stopRequested = runSettings().stopRequested;
  for (const auto &[name, value] : variables())
    s.variables.emplace_back(name, value);
  s.nextOutput = nextOutput_;
  s.nextCheckpoint = nextCheckpoint_;
  if (output_) {
    s.seriesByTime = output_->seriesByTime();
    for (const RunOutput::Written &w : output_->written())
      if (!(lastOnlyFrame_ && w.step == lastOnlyFrame_))
        s.frames.push_back(w);
  }
  s.shards = shards;
  s.particles = particles;
  return s;
}

void Run::checkpointWritten(const std::string &folder, std::uint64_t step, double seconds) {
  if (writes_ && !programOptions().quiet)
    std::printf("wash: checkpoint of iteration %llu written to %s in %.3f s\n",
                (unsigned long long)step, folder.c_str(), seconds);
  std::fflush(stdout);
  stepStart_ = Clock::now();
  stepCpuStart_ = processCpuSeconds();
}

std::uint64_t Run::resume(const CheckpointState &saved, std::size_t particles,
                          const std::string &folder, double readSeconds) {
  // The variables main added must be the checkpoint's (their values are its).
  std::map<std::string, double> &vars = variables();
  bool same = vars.size() == saved.variables.size();
  for (const auto &[name, value] : saved.variables)
    same &= vars.count(name) == 1;
  if (!same)
    throw RunError("cannot restart from checkpoint '" + folder +
                   "': its variables differ from those this program adds");
  for (const auto &[name, value] : saved.variables)
    vars[name] = value;
  SimTime &t = simTime();
  t.time = saved.time;
  t.step = saved.timeStep;
  t.stepSet = saved.timeStepSet;
  runSettings().stopRequested = saved.stopRequested;
  nextOutput_ = saved.nextOutput;
  nextCheckpoint_ = saved.nextCheckpoint;
  if (saved.stopRequested || endTimeReached())
    steps_ = saved.iteration; // the checkpoint's iteration was the last
  else if (steps_ < saved.iteration)
    throw RunError("cannot restart from checkpoint '" + folder + "' of iteration " +
                   std::to_string(saved.iteration) + ": the run ends after iteration " +
                   std::to_string(steps_) + " (--steps or set_max_iterations)");
  if (output_)
    output_->continueSeries(saved.frames, saved.seriesByTime);
  started(particles);
  if (writes_ && !programOptions().quiet)
    std::printf("wash: restarting from %s, after iteration %llu (t = %.17g), read in %.3f s\n",
                folder.c_str(), (unsigned long long)saved.iteration, saved.time, readSeconds);
  std::fflush(stdout);
  runStage() = {particles, saved.iteration + 1, true, steps_};
  watchStopSignals();
  startStepClocks();
  return firstStep_ = saved.iteration + 1;
}

bool Run::frameDue(std::uint64_t step) const {
  return detail::frameDue(programOptions(), step, steps_);
}

void Run::reserve(const Frame &frame) {
  if (!output_)
    return;
  output_->checkFields(frame);
  output_->reserve(frameBytesEstimate(frame, runStage().particles)); // every process's rows
}

void Run::write(std::uint64_t step, const Frame &frame) {
  const ProfileScope profiled("output (frames)");
  if (output_)
    output_->writeFrame(step, frame, simTime().time, /*seriesByTime=*/simTime().stepSet);
}

void Run::report(const std::string &line) const {
  if (writes_ && !programOptions().quiet)
    std::printf("%s\n", line.c_str());
}

void Run::started(std::size_t particles) {
  const bool talk = writes_ && !programOptions().quiet;
  if (talk) {
    std::string length = std::to_string(steps_) + " steps";
    if (endTime_) {
      char until[64];
      std::snprintf(until, sizeof until, "until t = %g", *endTime_);
      length =
          steps_ == std::numeric_limits<std::uint64_t>::max() ? until : length + " or " + until;
    }
    std::printf("wash %s: '%s', %zu particles, %dD, %s, %s, %s\n", backend_.c_str(),
                runSettings().simulationName.c_str(), particles, dimensions_,
                useFloat_ ? "float" : "double", runSettings().search.describe().c_str(),
                length.c_str());
  }
  std::fflush(stdout);
  progress_ = std::make_unique<Progress>(steps_, particles, talk, endTime_);
}

void Run::startStepClocks() {
  if (profiling)
    profileReset("(before the first kernel)");
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  involuntarySwitchesAtStart_ = usage.ru_nivcsw;
  stepStart_ = Clock::now();
  stepCpuStart_ = processCpuSeconds();
}

void Run::finish(const Frame &finalFrame) {
  const std::vector<ProfiledPhase> phases =
      profiling ? profiledPhases() : std::vector<ProfiledPhase>{};
  double seconds = progress_->finish();
  if (!output_)
    return;
  output_->finish(finalFrame);
  const std::uint64_t particles = runStage().particles; // finalFrame: this process's rows
  const std::uint64_t ran = steps_ >= firstStep_ ? steps_ - firstStep_ + 1 : 0; // after a restart
  const double particleSteps = double(ran) * double(particles);
  const std::string whose =
      processes() ? "rank 0 of " + std::to_string(processes()->count()) : "this process";
  if (writes_ && profiling) // asked for: printed even with --quiet
    std::printf("%s", profileTable(phases, ran, particleSteps, whose).c_str());
  if (!writes_ || programOptions().quiet) {
    std::fflush(stdout);
    return;
  }
  auto perParticleStep = [&](double s) {
    return particleSteps > 0 ? s * 1e9 / particleSteps : 0.0;
  };
  std::printf("wash: %llu steps of %zu particles in %.2f s (%.3g particle-steps/s); "
              "steps alone %.3f s, %.1f ns per particle-step wall, CPU %.3f s, %.1f ns per "
              "particle-step (%s, %d thread%s); output in %s\n",
              (unsigned long long)ran, std::size_t(particles), seconds,
              seconds > 0 ? particleSteps / seconds : 0.0, stepSeconds_,
              perParticleStep(stepSeconds_), stepCpuSeconds_, perParticleStep(stepCpuSeconds_),
              whose.c_str(), loopThreads, loopThreads == 1 ? "" : "s",
              output_->directory().c_str());
  reportCpu();
  std::fflush(stdout);
}

bool coresWereBusy(double cpuSeconds, double wallSeconds, int threads, long preemptions) {
  // Threads that wait sleep (docs/backends.md), so a share well below 1 with
  // few preemptions is idle threads (serial parts of a step); with many, the
  // cores were busy with other processes.
  constexpr double lowShare = 0.7, preemptionsPerSecond = 50.0;
  return wallSeconds > 0 && cpuSeconds < lowShare * wallSeconds * threads &&
         double(preemptions) >= preemptionsPerSecond * wallSeconds;
}

void Run::reportCpu() const {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const long preempted = usage.ru_nivcsw - involuntarySwitchesAtStart_;
  if (!coresWereBusy(stepCpuSeconds_, stepSeconds_, loopThreads, preempted))
    return;
  const double share = stepCpuSeconds_ / (stepSeconds_ * loopThreads);
  std::printf("wash: warning: the steps got %.0f%% of the CPU time of %d thread%s (%.2f s of CPU "
              "in %.2f s) and were preempted %ld times: other processes are running on these "
              "cores, and the times above are theirs as much as this program's. For a true "
              "figure run on idle cores or on fewer threads (OMP_NUM_THREADS); on a busy machine "
              "WASH_SHARED_MACHINE=1 makes waiting threads sleep; see "
              "docs/backends.md, \"Threads on a shared machine\"\n",
              100.0 * share, loopThreads, loopThreads == 1 ? "" : "s", stepCpuSeconds_,
              stepSeconds_, preempted);
}

void Run::checkFinite(const Frame &frame, std::uint64_t step, const std::string &kernel) const {
  if (std::string bad = findNonFinite(frame); !bad.empty())
    throw RunError(afterKernel(step, kernel) + bad);
}

void Run::failWith(std::uint64_t step, const char *kernel, const char *field, std::uint64_t id,
                   double value) const {
  throw RunError(afterKernel(step, kernel) + nonFiniteMessage(field, id, value));
}

} // namespace wash::detail
