//===- particle.cpp - Particle handles of the reference runtime --------===//
#include "state.hpp"

#include <cstring>
#include <new>

namespace wash {

using detail::ParticleStore;
using detail::state;

std::size_t Particle::get_id() const { return store_->id[index_]; }

namespace {

/// Where the translator's NeighbourWrite points for `x.setter(...)`: at the
/// setter's name. g++ places the call at the '(' right after the name, so the
/// name starts that many columns earlier; clang places it at the start of
/// `x`, which no column arithmetic can turn into the name's.
CallSite atSetterName(const CallSite &loc, const char *setter) {
#if defined(__clang__)
  return loc;
#else
  const auto length = static_cast<unsigned>(std::strlen(setter));
  return CallSite(loc.file_name(), loc.line(),
                  loc.column() > length ? loc.column() - length : loc.column());
#endif
}

/// Stops the run if `store` is a force kernel's snapshot of the neighbours:
/// the translator rejects such a write (NeighbourWrite) with this message.
void checkWritable(const ParticleStore *store, const char *setter,
                   const CallSite &loc) {
  if (store->neighbours)
    detail::usageError(atSetterName(loc, setter),
                       std::string("'") + setter +
                           "' writes to a neighbour particle; neighbours are read-only");
}

} // namespace

ParticleVec Particle::get_pos() const { return image_ ? *image_ : store_->pos[index_]; }
void Particle::set_pos(const ParticleVec &pos, Location loc) {
  checkWritable(store_, "set_pos", loc);
  store_->pos[index_] = state().store(pos);
}
ParticleVec Particle::get_vel() const { return store_->vel[index_]; }
void Particle::set_vel(const ParticleVec &vel, Location loc) {
  checkWritable(store_, "set_vel", loc);
  store_->vel[index_] = state().store(vel);
}
ParticleVec Particle::get_acc() const { return store_->acc[index_]; }
void Particle::set_acc(const ParticleVec &acc, Location loc) {
  checkWritable(store_, "set_acc", loc);
  store_->acc[index_] = state().store(acc);
}
double Particle::get_density() const { return store_->density[index_]; }
void Particle::set_density(double density, Location loc) {
  checkWritable(store_, "set_density", loc);
  store_->density[index_] = state().store(density);
}
double Particle::get_mass() const { return store_->mass[index_]; }
void Particle::set_mass(double mass, Location loc) {
  checkWritable(store_, "set_mass", loc);
  store_->mass[index_] = state().store(mass);
}
double Particle::get_smoothing_length() const { return store_->smoothingLength[index_]; }
void Particle::set_smoothing_length(double h, Location loc) {
  checkWritable(store_, "set_smoothing_length", loc);
  store_->smoothingLength[index_] = state().store(h);
}

bool Particle::is_type(const std::string &name, Location loc) const {
  return store_->type[index_] == state().typeIndex(name, loc);
}
void Particle::set_type(const std::string &name, Location loc) {
  checkWritable(store_, "set_type", loc);
  if (!state().typesSettable)
    detail::usageError(loc, "'set_type' outside an init or update kernel; a particle's type is "
                            "set only by init kernels and update kernels");
  store_->type[index_] = state().typeIndex(name, loc);
}

namespace {

/// Column `slot` of `columns`, grown to the store's size (new entries zero).
template <typename T>
std::vector<T> &column(std::vector<std::vector<T>> &columns, std::size_t slot, std::size_t size,
                       const std::string &name) {
  try {
    if (columns.size() <= slot)
      columns.resize(slot + 1);
    columns[slot].resize(size, T{});
  } catch (const std::bad_alloc &) {
    throw detail::outOfMemory("force '" + name + "'", size, sizeof(T));
  }
  return columns[slot];
}

/// Element `index` of column `slot`, or zero if that column was never written.
template <typename T>
T element(const std::vector<std::vector<T>> &columns, std::size_t slot, std::size_t index) {
  if (slot >= columns.size() || index >= columns[slot].size())
    return T{};
  return columns[slot][index];
}

} // namespace

double Particle::get_force_scalar(const std::string &name, Location loc) const {
  return element(store_->scalars, state().force(name, false, loc).slot, index_);
}

void Particle::set_force_scalar(const std::string &name, double value, Location loc) {
  checkWritable(store_, "set_force_scalar", loc);
  std::size_t slot = state().force(name, false, loc).slot;
  column(store_->scalars, slot, store_->size(), name)[index_] = state().store(value);
}

ParticleVec Particle::get_force_vector(const std::string &name, Location loc) const {
  return element(store_->vectors, state().force(name, true, loc).slot, index_);
}

void Particle::set_force_vector(const std::string &name, const ParticleVec &value, Location loc) {
  checkWritable(store_, "set_force_vector", loc);
  std::size_t slot = state().force(name, true, loc).slot;
  column(store_->vectors, slot, store_->size(), name)[index_] = state().store(value);
}

} // namespace wash
