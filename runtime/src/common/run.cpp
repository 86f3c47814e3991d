#include <wash/detail/run.hpp>

#include <cstdio>

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
  if (!o.steps && !s.maxIterations)
    throw RunError("no iteration count: call wash::set_max_iterations or pass --steps N");
  steps_ = o.steps ? *o.steps : *s.maxIterations;
  radius_ = s.search.radius.value_or(0.0);
  if (std::string bad = checkBox(s.box, dimensions_, radius_); !bad.empty())
    throw RunError(bad);
  if (writes_)
    output_ = std::make_unique<RunOutput>(o, s.outputBaseName());
}

Run::~Run() = default;

bool Run::frameDue(std::uint64_t step) const {
  return detail::frameDue(programOptions(), step, steps_);
}

void Run::reserve(const Frame &frame) {
  if (output_)
    output_->reserve(frameBytesEstimate(frame));
}

void Run::write(std::uint64_t step, const Frame &frame) {
  if (output_)
    output_->writeFrame(step, frame);
}

void Run::report(const std::string &line) const {
  if (writes_ && !programOptions().quiet)
    std::printf("%s\n", line.c_str());
}

void Run::started(std::size_t particles) {
  const bool talk = writes_ && !programOptions().quiet;
  if (talk)
    std::printf("wash %s: '%s', %zu particles, %dD, %s, %s, %llu steps\n", backend_.c_str(),
                runSettings().simulationName.c_str(), particles, dimensions_,
                useFloat_ ? "float" : "double", runSettings().search.describe().c_str(),
                (unsigned long long)steps_);
  std::fflush(stdout);
  progress_ = std::make_unique<Progress>(steps_, particles, talk);
}

void Run::finish(const Frame &finalFrame) {
  double seconds = progress_->finish();
  if (!output_)
    return;
  output_->finish(finalFrame);
  if (programOptions().quiet)
    return;
  const double particleSteps = double(steps_) * double(finalFrame.size());
  std::printf("wash: %llu steps of %zu particles in %.2f s (%.3g particle-steps/s); "
              "steps alone %.3f s, %.1f ns per particle-step; output in %s\n",
              (unsigned long long)steps_, finalFrame.size(), seconds,
              seconds > 0 ? particleSteps / seconds : 0.0, stepSeconds_,
              particleSteps > 0 ? stepSeconds_ * 1e9 / particleSteps : 0.0,
              output_->directory().c_str());
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
