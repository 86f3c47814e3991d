#include <wash/backend/run.hpp>

#include <cstdio>
#include <sstream>

namespace wash::backend {

Run::Run(const Translation &translated, bool writes)
    : backend_(translated.backend), dimensions_(translated.dimensions),
      useFloat_(translated.floatStorage), writes_(writes) {
  const bool translatedForFloat = translated.floatStorage;
  const bool translatedForSupport = translated.smoothingLengthSearch;
  const int dimensions = translated.dimensions;
  const Settings &s = settings();
  const detail::RunOptions &o = programOptions();
  if (s.useFloat && *s.useFloat != translatedForFloat)
    throw detail::RunError(std::string("this program was translated for ") +
                           (translatedForFloat ? "float" : "double") +
                           " precision, but main asked for " + (*s.useFloat ? "float" : "double"));
  if (std::string bad = s.search.check(); !bad.empty())
    throw detail::RunError(bad);
  if (s.search.perParticle() != translatedForSupport)
    throw detail::RunError(std::string("this program was translated for ") +
                           (translatedForSupport ? "a smoothing-length" : "an influence-radius") +
                           " neighbour search, but main asked for " +
                           (translatedForSupport ? "an influence radius" : "smoothing lengths") +
                           "; call the neighbour-rule setting unconditionally in main");
  if (!o.steps && !s.maxIterations)
    throw detail::RunError("no iteration count: call wash::set_max_iterations or pass --steps N");
  steps_ = o.steps ? *o.steps : *s.maxIterations;
  radius_ = s.search.radius.value_or(0.0);
  if (std::string bad = detail::checkBox(s.box, dimensions, radius_); !bad.empty())
    throw detail::RunError(bad);
  if (writes_)
    output_ = std::make_unique<detail::RunOutput>(o, s.outputBaseName());
}

bool Run::frameDue(std::uint64_t step) const {
  return detail::frameDue(programOptions(), step, steps_);
}

void Run::write(std::uint64_t step, const detail::Frame &frame) {
  if (output_)
    output_->writeFrame(step, frame);
}

void Run::report(const std::string &line) const {
  if (writes_ && !programOptions().quiet)
    std::printf("%s\n", line.c_str());
}

Run::~Run() = default;

void Run::started(std::size_t particles) {
  const bool talk = writes_ && !programOptions().quiet;
  if (talk)
    std::printf("wash %s: '%s', %zu particles, %dD, %s, %s, %llu steps\n", backend_.c_str(),
                settings().simulationName.c_str(), particles, dimensions_,
                useFloat_ ? "float" : "double", settings().search.describe().c_str(),
                (unsigned long long)steps_);
  std::fflush(stdout);
  progress_ = std::make_unique<detail::Progress>(steps_, particles, talk);
}

void Run::finish(const detail::Frame &finalFrame) {
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

void Run::failWith(std::uint64_t step, const char *kernel, const char *field, std::uint64_t id,
                   double value) const {
  std::ostringstream msg;
  msg << "step " << step << ": after kernel '" << kernel << "': field '" << field
      << "' of particle " << id << " is " << value;
  throw detail::RunError(msg.str());
}

} // namespace wash::backend
