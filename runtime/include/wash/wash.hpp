//===- wash/wash.hpp - the one header a wash simulation includes -*- C++ -*-===//
//
// A simulation is one C++ file: constants, a `main` that configures the run and
// registers forces and kernels in order, and kernels written for one particle.
// Compiled as it is against this header and the reference runtime it is the
// untranslated program that defines what the simulation means (docs/semantics.md).
// The `wash` translator reads the same file and emits a specialised program.
//
// The dimension of a simulation is fixed at compile time by WASH_DIM (2 or 3).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/math.hpp>
#include <wash/random.hpp>
#include <wash/settings.hpp>
#include <wash/vec.hpp>

#include <cstddef>
#include <cstdint>
#include <wash/call_site.hpp>
#include <string>
#include <vector>

#ifndef WASH_DIM
#define WASH_DIM 2
#endif

namespace wash {

/// Number of spatial dimensions of this program.
inline constexpr int dimensions = WASH_DIM;
/// The vector type of particle positions, velocities and vector forces.
using ParticleVec = Vec<double, WASH_DIM>;

namespace detail {
struct ParticleStore;
}

/// A handle to one particle. Kernels receive their own particle as `Particle&`
/// and its neighbours as `const std::vector<Particle>&`: neighbours are read-only
/// (a setter called on one, through a cast or a copy of the handle, stops the
/// run with the caller's location).
class Particle {
public:
  using Location = CallSite;

  /// Creation index: 0, 1, 2, ... in the order create_particle was called.
  std::size_t get_id() const;

  ParticleVec get_pos() const;
  void set_pos(const ParticleVec &pos, Location loc = Location::current());
  ParticleVec get_vel() const;
  void set_vel(const ParticleVec &vel, Location loc = Location::current());
  ParticleVec get_acc() const;
  void set_acc(const ParticleVec &acc, Location loc = Location::current());
  double get_density() const;
  void set_density(double density, Location loc = Location::current());
  double get_mass() const;
  void set_mass(double mass, Location loc = Location::current());
  double get_smoothing_length() const;
  void set_smoothing_length(double smoothingLength, Location loc = Location::current());

  /// A named per-particle property ("force"). A name never passed to add_force
  /// is created on first use; using one name both as scalar and vector is an error.
  double get_force_scalar(const std::string &name, Location loc = Location::current()) const;
  void set_force_scalar(const std::string &name, double value,
                        Location loc = Location::current());
  ParticleVec get_force_vector(const std::string &name, Location loc = Location::current()) const;
  void set_force_vector(const std::string &name, const ParticleVec &value,
                        Location loc = Location::current());

  /// Particle types (wash::add_particle_type; docs/semantics.md): whether this
  /// particle, itself or a neighbour, is of type `name`.
  bool is_type(const std::string &name, Location loc = Location::current()) const;
  /// Makes this particle one of type `name`: from init kernels, and from
  /// update kernels on their own particle.
  void set_type(const std::string &name, Location loc = Location::current());

  /// A handle on particle `index` of `store`; a neighbour across a periodic
  /// face also carries the image's position.
  Particle(detail::ParticleStore *store, std::size_t index, const ParticleVec *image = nullptr)
      : store_(store), index_(index), image_(image) {}

private:
  detail::ParticleStore *store_;
  std::size_t index_;
  const ParticleVec *image_;
};

using InitKernel = void (*)();
using UpdateKernel = void (*)(Particle &);
using ForceKernel = void (*)(Particle &, const std::vector<Particle> &);
using VoidKernel = void (*)();
using ReductionKernel = double (*)(const Particle &);

/// How a reduction kernel combines its particles' values. Sum is their exact
/// sum rounded once to nearest (so every backend gets the same bits, in any
/// order; docs/semantics.md); Min and Max of no particles are +inf and -inf.
enum class Reduction { Sum, Min, Max };

/// Registers a named property: dim 1 is a scalar, dim == WASH_DIM a vector.
void add_force(const std::string &name, int dim,
               CallSite loc = CallSite::current());

/// Adds a particle type (in main, before start). The first one added is the
/// type of every particle create_particle makes; a type's index in output is
/// its position in the order of these calls.
void add_particle_type(const std::string &name, CallSite loc = CallSite::current());

/// Kernels run in registration order: init kernels once, then every iteration
/// each update kernel (per particle) and force kernel (per particle, with its
/// neighbours) in the order they were added. A particle type restricts a
/// kernel to the particles of that type ("" = every particle); a force
/// kernel's neighbour type keeps only the neighbours of that type.
void add_init_kernel(InitKernel kernel);
void add_update_kernel(UpdateKernel kernel, const std::string &type = "",
                       CallSite loc = CallSite::current());
void add_force_kernel(ForceKernel kernel, const std::string &type = "",
                      const std::string &neighbourType = "", CallSite loc = CallSite::current());
/// A kernel run once per iteration at its place in the order, for no particle
/// (to update global variables, say).
void add_void_kernel(VoidKernel kernel);
/// A kernel run once per iteration at its place in the order: `variable` (added
/// with add_variable) becomes the Sum, Min or Max over all particles of f(p),
/// or over the particles of `type`.
void add_reduction_kernel(ReductionKernel kernel, Reduction op, const std::string &variable,
                          const std::string &type = "", CallSite loc = CallSite::current());

/// Adds a particle (only from an init kernel). The reference stays valid until
/// the next create_particle call.
Particle &create_particle(double density, double mass, double smoothingLength,
                          const ParticleVec &pos, const ParticleVec &vel,
                          CallSite loc = CallSite::current());

/// Runs the simulation: init kernels, then max_iterations iterations, writing
/// output as the program options ask. Exits the program with a message on error.
void start();

/// Ends the run after the current iteration, which then counts as the last
/// one (its frame is written as the final output). For a run to a simulated
/// end time: only void kernels may call it, so every rank agrees when.
void stop(CallSite loc = CallSite::current());

/// Marks a per-particle kernel that deliberately changes shared state (a
/// global or static variable, a global random engine, std::rand): the
/// translator then accepts it, although its result depends on the order
/// particles run in and so differs between backends and ranks. Call it in
/// the kernel's own body; it does nothing at run time. For random numbers
/// use wash::random instead, which is the same everywhere.
inline void allow_shared_state() {}

} // namespace wash

// Program options. The runtime strips the wash options (--steps, --out, ...;
// see --help) from argv before the simulation's own `main` sees it: the wash
// targets link with `-Wl,--wrap=main`, so the runtime's __wrap_main runs first
// and calls the simulation's main with what is left.
