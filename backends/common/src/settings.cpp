// wash/settings.hpp for generated programs: the same checks as the reference.
#include <wash/backend/run.hpp>
#include <wash/detail/variables.hpp>
#include <wash/settings.hpp>

namespace wash {

using detail::usageErrorAt;

void set_precision(const std::string &precision, std::source_location loc) {
  if (precision != "double" && precision != "float")
    usageErrorAt(loc, "precision must be \"double\" or \"float\", not \"" + precision + "\"");
  backend::settings().useFloat = precision == "float";
}

void set_influence_radius(double radius, std::source_location loc) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    usageErrorAt(loc, "influence radius must be a positive number");
  backend::settings().search.radius = radius;
}

void set_smoothing_length_support(double support, std::source_location loc) {
  if (!(support > 0.0) || !std::isfinite(support))
    usageErrorAt(loc, "the support radius must be a positive multiple of h");
  backend::settings().search.support = support;
}

void set_bounding_box(const std::vector<double> &lo, const std::vector<double> &hi,
                      const std::vector<bool> &periodic, std::source_location loc) {
  if (!detail::setBox(backend::settings().box, backend::settings().dimensions, lo, hi, periodic))
    usageErrorAt(loc, "set_bounding_box needs " + std::to_string(backend::settings().dimensions) +
                        " values for lo, hi and periodic, with hi > lo on every axis");
}

void stop(std::source_location) { backend::settings().stopRequested = true; }

void set_simulation_name(const std::string &name) { backend::settings().simulationName = name; }
void set_output_file_name(const std::string &name) { backend::settings().outputFileName = name; }
void set_max_iterations(std::uint64_t iterations) {
  backend::settings().maxIterations = iterations;
}

} // namespace wash
