//===- state.hpp - the reference runtime's particles and kernels -*- C++ -*-===//
//
// Internal to the reference runtime. Particles live in one store, column by
// column; a Particle is (store, index), so a force kernel's neighbours are
// handles into a snapshot copy of the store taken when the kernel starts.
// main's settings are in the store every runtime shares (run_settings.hpp).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/frame.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/wash.hpp>

#include <cstdint>
#include <wash/call_site.hpp>
#include <string>
#include <vector>

namespace wash::detail {

struct ParticleStore {
  std::vector<std::uint64_t> id;
  std::vector<ParticleVec> pos, vel, acc;
  std::vector<double> density, mass, smoothingLength;
  /// Each particle's type: an index into State::types (0 when there are none).
  std::vector<std::uint32_t> type;
  /// Force columns by slot; a column shorter than the store reads as zeros.
  std::vector<std::vector<double>> scalars;
  std::vector<std::vector<ParticleVec>> vectors;
  /// A force kernel's snapshot, read through neighbour handles: not writable.
  bool neighbours = false;

  std::size_t size() const { return id.size(); }
};

struct Force {
  std::string name;
  bool isVector = false;
  bool registered = false; ///< by add_force, rather than created on first use
  std::size_t slot = 0;    ///< column in ParticleStore::scalars or ::vectors
};

struct Kernel {
  enum Kind { Init, Update, ForceKind, Void, ReductionKind } kind;
  void *function;
  std::string name;     ///< from the symbol table, for messages
  int reduceOp = 0;     ///< reduction kernels: a wash::Reduction
  std::string variable; ///< reduction kernels: where the result goes
  /// The particle type it runs for, and a force kernel's neighbours' type
  /// (indices into State::types; -1: every type).
  int type = -1, neighbourType = -1;
};

/// What a reference run knows besides main's settings. One per program.
struct State {
  std::vector<Force> forces;
  std::vector<Kernel> kernels;
  /// Particle types in the order they were added (none: an untyped simulation).
  std::vector<std::string> types;
  ParticleStore particles;
  bool inInitKernel = false;
  bool inVoidKernel = false;
  /// An init or update kernel is running: set_type is allowed.
  bool typesSettable = false;
  bool started = false;

  /// Storage rounding: the stored value of v under the chosen precision.
  double store(double v) const;
  ParticleVec store(ParticleVec v) const {
    for (int k = 0; k < dimensions; ++k)
      *v[k] = store(v.at(k));
    return v;
  }

  /// The index of particle type `name`; a misuse if there is none.
  std::uint32_t typeIndex(const std::string &name, const CallSite &loc) const;
  /// The type a kernel registration names ("": every type, -1).
  int kernelType(const std::string &name, const CallSite &loc) const;

  /// The force `name` as a scalar or vector, created on first use.
  const Force &force(const std::string &name, bool isVector, const CallSite &loc);
  /// Columns in output order: pos, vel, density, mass, smoothing_length, then
  /// forces registered with add_force in that order, then created ones by
  /// name, then (typed simulations only) type.
  Frame frame(const ParticleStore &store) const;
};

State &state();

/// A misuse of the API, reported at the caller's source location.
[[noreturn]] void usageError(const CallSite &loc, const std::string &message);

} // namespace wash::detail
