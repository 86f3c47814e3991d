//===- api.cpp - registration calls of the reference runtime ------------===//
//
// The settings calls are every runtime's (src/common/run_settings.cpp).
//
//===----------------------------------------------------------------------===//
#include "state.hpp"

#include <wash/detail/sim_time.hpp>

#include <cxxabi.h>
#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <memory>
#include <new>

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
  std::string fallback =
      std::string(kindName) + " kernel #" + std::to_string(state().kernels.size() + 1);
  state().kernels.push_back({kind, function, symbolName(function, fallback.c_str())});
}

} // namespace

void add_force(const std::string &name, int dim, CallSite loc) {
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

void add_particle_type(const std::string &name, CallSite loc) {
  auto &s = state();
  if (s.started)
    usageError(loc, "particle type '" + name + "' was added after start()");
  // Type names go into generated code and output files: identifiers only.
  const bool identifier =
      !name.empty() && !std::isdigit((unsigned char)name[0]) &&
      std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum((unsigned char)c) || c == '_'; });
  if (!identifier)
    usageError(loc, "particle type name '" + name +
                        "' is not an identifier ([A-Za-z_][A-Za-z0-9_]*)");
  for (const std::string &t : s.types)
    if (t == name)
      usageError(loc, "particle type '" + name + "' is already added");
  s.types.push_back(name);
}

void add_init_kernel(InitKernel kernel) {
  addKernel(detail::Kernel::Init, reinterpret_cast<void *>(kernel), "init");
}
void add_update_kernel(UpdateKernel kernel, const std::string &type, CallSite loc) {
  const int t = state().kernelType(type, loc);
  addKernel(detail::Kernel::Update, reinterpret_cast<void *>(kernel), "update");
  state().kernels.back().type = t;
}
void add_force_kernel(ForceKernel kernel, const std::string &type,
                      const std::string &neighbourType, CallSite loc) {
  const int t = state().kernelType(type, loc), n = state().kernelType(neighbourType, loc);
  addKernel(detail::Kernel::ForceKind, reinterpret_cast<void *>(kernel), "force");
  state().kernels.back().type = t;
  state().kernels.back().neighbourType = n;
}
void add_void_kernel(VoidKernel kernel) {
  addKernel(detail::Kernel::Void, reinterpret_cast<void *>(kernel), "void");
}
void add_reduction_kernel(ReductionKernel kernel, Reduction op, const std::string &variable,
                          const std::string &type, CallSite loc) {
  if (variable != detail::timeStepTarget)
    get_variable(variable, loc); // it must exist
  const int t = state().kernelType(type, loc);
  addKernel(detail::Kernel::ReductionKind, reinterpret_cast<void *>(kernel), "reduction");
  state().kernels.back().type = t;
  state().kernels.back().reduceOp = int(op);
  state().kernels.back().variable = variable;
}

Particle &create_particle(double density, double mass, double smoothingLength,
                          const ParticleVec &pos, const ParticleVec &vel,
                          CallSite loc) {
  auto &s = state();
  if (!s.inInitKernel)
    usageError(loc, "create_particle can only be called from an init kernel");
  auto &store = s.particles;
  const std::size_t index = store.size();
  try {
    store.id.push_back(index);
    store.pos.push_back(s.store(pos));
    store.vel.push_back(s.store(vel));
    store.acc.push_back(ParticleVec{});
    store.density.push_back(s.store(density));
    store.mass.push_back(s.store(mass));
    store.smoothingLength.push_back(s.store(smoothingLength));
    store.type.push_back(0); // the first type added
  } catch (const std::bad_alloc &) {
    // The builtin columns; forces are allocated when first written.
    const std::size_t bytesEach =
        sizeof(std::uint64_t) + 3 * sizeof(ParticleVec) + 3 * sizeof(double) +
        sizeof(std::uint32_t);
    throw detail::outOfMemory("the particle store (create_particle)", index + 1, bytesEach);
  }
  static Particle created(nullptr, 0);
  created = Particle(&store, store.size() - 1);
  return created;
}

} // namespace wash
