// wash/settings.hpp's run settings, with their checks: the same code for the
// reference runtime and every backend (the variables are in variables.cpp).
#include <wash/detail/run_settings.hpp>
#include <wash/detail/variables.hpp>
#include <wash/settings.hpp>

#include <cmath>

namespace wash {
namespace detail {

RunSettings &runSettings() {
  static RunSettings s;
  return s;
}

RunOptions &programOptions() {
  static RunOptions o;
  return o;
}

} // namespace detail

using detail::runSettings;
using detail::usageErrorAt;

void set_precision(const std::string &precision, CallSite loc) {
  if (precision != "double" && precision != "float")
    usageErrorAt(loc, "precision must be \"double\" or \"float\", not \"" + precision + "\"");
  runSettings().useFloat = precision == "float";
}

void set_influence_radius(double radius, CallSite loc) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    usageErrorAt(loc, "influence radius must be a positive number");
  runSettings().search.radius = radius;
}

void set_smoothing_length_support(double support, Support rule, CallSite loc) {
  if (!(support > 0.0) || !std::isfinite(support))
    usageErrorAt(loc, "the support radius must be a positive multiple of h");
  if (rule != Support::Gather && rule != Support::Symmetric)
    usageErrorAt(loc, "the support rule must be wash::Support::Gather or wash::Support::Symmetric");
  runSettings().search.support = support;
  runSettings().search.symmetric = rule == Support::Symmetric;
}

void set_bounding_box(const std::vector<double> &lo, const std::vector<double> &hi,
                      const std::vector<bool> &periodic, CallSite loc) {
  detail::RunSettings &s = runSettings();
  if (!detail::setBox(s.box, s.dimensions, lo, hi, periodic))
    usageErrorAt(loc, "set_bounding_box needs " + std::to_string(s.dimensions) +
                          " values for lo, hi and periodic, with hi > lo on every axis");
}

void set_simulation_name(const std::string &name) { runSettings().simulationName = name; }
void set_output_file_name(const std::string &name) { runSettings().outputFileName = name; }
void set_max_iterations(std::uint64_t iterations) { runSettings().maxIterations = iterations; }

} // namespace wash
