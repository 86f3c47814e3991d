// wash/settings.hpp's global variables: the same in the reference and every backend.
#include <wash/detail/run_output.hpp>
#include <wash/detail/sim_time.hpp>
#include <wash/detail/variables.hpp>
#include <wash/settings.hpp>

namespace wash {
namespace detail {

std::map<std::string, double> &variables() {
  static std::map<std::string, double> v;
  return v;
}

void usageErrorAt(const CallSite &loc, const std::string &message) {
  throw UsageError(std::string(loc.file_name()) + ":" + std::to_string(loc.line()) + ":" +
                   std::to_string(loc.column()) + ": error: " + message);
}

} // namespace detail

void add_variable(const std::string &name, double initial, CallSite loc) {
  if (name == detail::timeStepTarget)
    detail::usageErrorAt(loc, "'time_step' is not a variable name: a reduction kernel with that "
                              "target sets the time step (wash::get_time_step)");
  if (!detail::variables().emplace(name, initial).second)
    detail::usageErrorAt(loc, "variable '" + name + "' is added twice");
}

double get_variable(const std::string &name, CallSite loc) {
  auto it = detail::variables().find(name);
  if (it == detail::variables().end())
    detail::usageErrorAt(loc, "variable '" + name + "' was never added (wash::add_variable)");
  return it->second;
}

void set_variable(const std::string &name, double value, CallSite loc) {
  auto it = detail::variables().find(name);
  if (it == detail::variables().end())
    detail::usageErrorAt(loc, "variable '" + name + "' was never added (wash::add_variable)");
  it->second = value;
}

} // namespace wash
