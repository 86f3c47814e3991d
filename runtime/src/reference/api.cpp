//===- api.cpp - settings and registration calls of the reference runtime ===//
#include "state.hpp"

#include <cxxabi.h>
#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <memory>

namespace wash {

using detail::state;
using detail::usageError;

namespace {

/// The function's name from the dynamic symbol table (the wash targets link
/// with -rdynamic), so that messages can name the kernel.
std::string symbolName(void *function, const char *fallback) {
  Dl_info info;
  if (!dladdr(function, &info) || !info.dli_sname)
    return fallback;
  int status = 0;
  std::unique_ptr<char, decltype(&std::free)> demangled(
      abi::__cxa_demangle(info.dli_sname, nullptr, nullptr, &status), &std::free);
  std::string name = status == 0 ? demangled.get() : info.dli_sname;
  return name.substr(0, name.find('('));
}

void addKernel(detail::Kernel::Kind kind, void *function, const char *kindName) {
  if (!function)
    throw detail::RunError(std::string("a null ") + kindName + " kernel was registered");
  if (state().started)
    throw detail::RunError(std::string("a ") + kindName + " kernel was registered after start()");
  std::string fallback = std::string(kindName) + " kernel #" +
                         std::to_string(state().kernels.size() + 1);
  state().kernels.push_back({kind, function, symbolName(function, fallback.c_str())});
}

} // namespace

void set_precision(const std::string &precision, std::source_location loc) {
  if (precision != "double" && precision != "float")
    usageError(loc, "precision must be \"double\" or \"float\", not \"" + precision + "\"");
  state().useFloat = precision == "float";
}

void set_influence_radius(double radius, std::source_location loc) {
  if (!(radius > 0.0) || !std::isfinite(radius))
    usageError(loc, "influence radius must be a positive number");
  state().search.radius = radius;
}

void set_smoothing_length_support(double support, std::source_location loc) {
  if (!(support > 0.0) || !std::isfinite(support))
    usageError(loc, "the support radius must be a positive multiple of h");
  state().search.support = support;
}

void set_bounding_box(const std::vector<double> &lo, const std::vector<double> &hi,
                      const std::vector<bool> &periodic, std::source_location loc) {
  auto &box = state().box;
  if (!detail::setBox(box, dimensions, lo, hi, periodic))
    usageError(loc, "set_bounding_box needs " + std::to_string(dimensions) +
                        " values for lo, hi and periodic, with hi > lo on every axis");
}

void set_simulation_name(const std::string &name) { state().simulationName = name; }
void set_output_file_name(const std::string &name) { state().outputFileName = name; }
void set_max_iterations(std::uint64_t iterations) { state().maxIterations = iterations; }

void add_force(const std::string &name, int dim, std::source_location loc) {
  if (dim != 1 && dim != dimensions)
    usageError(loc, "force '" + name + "' has dimension " + std::to_string(dim) +
                        "; use 1 (scalar) or " + std::to_string(dimensions) +
                        " (a vector in this " + std::to_string(dimensions) + "D program)");
  for (const detail::Force &f : state().forces)
    if (f.name == name)
      usageError(loc, "force '" + name + "' is already registered");
  state().force(name, dim != 1, loc);
  state().forces.back().registered = true;
}

void add_init_kernel(InitKernel kernel) {
  addKernel(detail::Kernel::Init, reinterpret_cast<void *>(kernel), "init");
}
void add_update_kernel(UpdateKernel kernel) {
  addKernel(detail::Kernel::Update, reinterpret_cast<void *>(kernel), "update");
}
void add_force_kernel(ForceKernel kernel) {
  addKernel(detail::Kernel::ForceKind, reinterpret_cast<void *>(kernel), "force");
}
void add_void_kernel(VoidKernel kernel) {
  addKernel(detail::Kernel::Void, reinterpret_cast<void *>(kernel), "void");
}
void add_reduction_kernel(ReductionKernel kernel, Reduction op, const std::string &variable,
                          std::source_location loc) {
  get_variable(variable, loc); // it must exist
  addKernel(detail::Kernel::ReductionKind, reinterpret_cast<void *>(kernel), "reduction");
  state().kernels.back().reduceOp = int(op);
  state().kernels.back().variable = variable;
}

Particle &create_particle(double density, double mass, double smoothingLength,
                          const ParticleVec &pos, const ParticleVec &vel,
                          std::source_location loc) {
  auto &s = state();
  if (!s.inInitKernel)
    usageError(loc, "create_particle can only be called from an init kernel");
  auto &store = s.particles;
  store.id.push_back(store.size());
  store.pos.push_back(s.store(pos));
  store.vel.push_back(s.store(vel));
  store.acc.push_back(ParticleVec{});
  store.density.push_back(s.store(density));
  store.mass.push_back(s.store(mass));
  store.smoothingLength.push_back(s.store(smoothingLength));
  static Particle created(nullptr, 0);
  created = Particle(&store, store.size() - 1);
  return created;
}

} // namespace wash
