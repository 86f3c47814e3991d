#include "state.hpp"

#include <wash/detail/run_settings.hpp>
#include <wash/detail/variables.hpp>

#include <algorithm>

// The shared settings' dimension is this build's WASH_DIM (set_bounding_box
// checks against it), set before main runs; runSettings() is a function-local
// static, so the order of static initialisers does not matter. Every program
// links this object, whatever it calls: the reference library makes the
// linker look for this symbol (runtime/CMakeLists.txt).
extern "C" const int wash_reference_dimensions =
    (wash::detail::runSettings().dimensions = WASH_DIM);

namespace wash::detail {

State &state() {
  static State s;
  return s;
}

void usageError(const CallSite &loc, const std::string &message) {
  usageErrorAt(loc, message);
}

// Out of line on purpose: g++ 12 at -O2, inlining this into the vector
// overload, vectorised the pair of round trips into a plain copy (the rounding
// was lost). Kept as a call, each conversion happens.
double State::store(double v) const {
  return runSettings().useFloat.value_or(false) ? double(float(v)) : v;
}

const Force &State::force(const std::string &name, bool isVector, const CallSite &loc) {
  for (const Force &f : forces) {
    if (f.name != name)
      continue;
    if (f.isVector != isVector)
      usageError(loc, "force '" + name + "' is a " + (f.isVector ? "vector" : "scalar") +
                          " but is used here as a " + (isVector ? "vector" : "scalar"));
    return f;
  }
  if (name.empty())
    usageError(loc, "force name is empty");
  Force f{name, isVector, false, 0};
  f.slot = std::count_if(forces.begin(), forces.end(),
                         [&](const Force &g) { return g.isVector == isVector; });
  forces.push_back(f);
  return forces.back();
}

std::uint32_t State::typeIndex(const std::string &name, const CallSite &loc) const {
  for (std::size_t t = 0; t < types.size(); ++t)
    if (types[t] == name)
      return std::uint32_t(t);
  usageError(loc, types.empty() ? "particle type '" + name +
                                      "' is unknown: no particle type was added "
                                      "(wash::add_particle_type)"
                                : "particle type '" + name + "' is unknown");
}

int State::kernelType(const std::string &name, const CallSite &loc) const {
  return name.empty() ? -1 : int(typeIndex(name, loc));
}

namespace {

void addScalar(Frame &frame, const std::string &name, const std::vector<double> &values,
               std::size_t n) {
  Column column{name, 1, std::vector<double>(n, 0.0)};
  std::copy_n(values.begin(), std::min(n, values.size()), column.values.begin());
  frame.columns.push_back(std::move(column));
}

void addVector(Frame &frame, const std::string &name, const std::vector<ParticleVec> &values,
               std::size_t n) {
  Column column{name, dimensions, std::vector<double>(n * dimensions, 0.0)};
  for (std::size_t p = 0; p < std::min(n, values.size()); ++p)
    for (int k = 0; k < dimensions; ++k)
      column.values[p * dimensions + k] = values[p].at(k);
  frame.columns.push_back(std::move(column));
}

} // namespace

Frame State::frame(const ParticleStore &store) const {
  const std::size_t n = store.size();
  Frame frame;
  frame.dimensions = dimensions;
  frame.ids = store.id;
  addVector(frame, "pos", store.pos, n);
  addVector(frame, "vel", store.vel, n);
  addVector(frame, "acc", store.acc, n);
  frame.columns.back().inDump = false; // frames only: --dump keeps its columns
  addScalar(frame, "density", store.density, n);
  addScalar(frame, "mass", store.mass, n);
  addScalar(frame, "smoothing_length", store.smoothingLength, n);
  std::vector<const Force *> order;
  for (const Force &f : forces)
    order.push_back(&f);
  std::stable_sort(order.begin(), order.end(), [](const Force *a, const Force *b) {
    if (a->registered != b->registered)
      return a->registered;
    return !a->registered && a->name < b->name;
  });
  static const std::vector<double> noScalars;
  static const std::vector<ParticleVec> noVectors;
  for (const Force *f : order) {
    if (f->isVector)
      addVector(frame, f->name, f->slot < store.vectors.size() ? store.vectors[f->slot] : noVectors,
                n);
    else
      addScalar(frame, f->name, f->slot < store.scalars.size() ? store.scalars[f->slot] : noScalars,
                n);
  }
  if (!types.empty()) {
    std::vector<double> type(store.type.begin(), store.type.end());
    addScalar(frame, "type", type, n);
    frame.typeNames = types;
  }
  return frame;
}

} // namespace wash::detail
