#include <wash/detail/processes.hpp>
#include <wash/detail/run.hpp>

#include <algorithm>
#include <cstdio>
#include <limits>

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
                   (*s.useFloat ? "float" : "double"));
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
}

std::string afterKernel(std::uint64_t step, const std::string &kernel) {
  return "step " + std::to_string(step) + ": after kernel '" + kernel + "': ";
}

} // namespace

Run::Run(const Translation &translated, bool writes)
    : backend_(translated.backend), dimensions_(translated.dimensions),
      useFloat_(checkedPrecision(translated, runSettings())), writes_(writes) {
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
  t.time += t.step;
  return outputTimeCrossed();
}

bool Run::outputTimeCrossed() {
  if (!outputDt_)
    return false;
  const double time = simTime().time, every = *outputDt_;
  if (time < double(nextOutput_) * every)
    return false;
  // The next multiple beyond the time (a long step may cross several: one frame).
  nextOutput_ = std::max(nextOutput_, std::uint64_t(std::floor(time / every)));
  while (double(nextOutput_) * every <= time)
    ++nextOutput_;
  return true;
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

void Run::finish(const Frame &finalFrame) {
  double seconds = progress_->finish();
  if (!output_)
    return;
  output_->finish(finalFrame);
  if (!writes_ || programOptions().quiet)
    return;
  const std::uint64_t particles = runStage().particles; // finalFrame: this process's rows
  const double particleSteps = double(steps_) * double(particles);
  std::printf("wash: %llu steps of %zu particles in %.2f s (%.3g particle-steps/s); "
              "steps alone %.3f s, %.1f ns per particle-step; output in %s\n",
              (unsigned long long)steps_, std::size_t(particles), seconds,
              seconds > 0 ? particleSteps / seconds : 0.0, stepSeconds_,
              particleSteps > 0 ? stepSeconds_ * 1e9 / particleSteps : 0.0,
              output_->directory().c_str());
  std::fflush(stdout);
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
