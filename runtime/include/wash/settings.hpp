//===- wash/settings.hpp - run settings, shared by every runtime -*- C++ -*-===//
//
// The calls a simulation's main makes to configure a run. The reference
// runtime and every backend runtime implement them with the same meaning.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <wash/call_site.hpp>
#include <string>
#include <vector>

namespace wash {

/// Storage precision of every particle property: "double" or "float".
void set_precision(const std::string &precision,
                   CallSite loc = CallSite::current());
/// Neighbours of a particle are the other particles within this distance.
void set_influence_radius(double radius,
                          CallSite loc = CallSite::current());
/// Which smoothing length bounds a pair under set_smoothing_length_support.
enum class Support {
  Gather,    ///< j is a neighbour of i within support * h_i
  Symmetric, ///< within support * max(h_i, h_j): i and j list each other
};

/// Instead of one radius: the neighbours of particle i are the other particles
/// within `support` * h_i of it (Support::Gather), or within
/// `support` * max(h_i, h_j) (Support::Symmetric), h being the smoothing
/// lengths when the force kernel starts, listed in ascending id order.
/// `support` is the kernel's support radius in units of h: 2 for the cubic
/// spline or Wendland kernels written as W(r, h) with support 2h. Call this or
/// set_influence_radius.
void set_smoothing_length_support(double support, Support rule = Support::Gather,
                                  CallSite loc = CallSite::current());
void set_simulation_name(const std::string &name);
/// Base name of output files (default: the simulation name).
void set_output_file_name(const std::string &name);
/// Number of iterations start() runs (the --steps option overrides it).
void set_max_iterations(std::uint64_t iterations);

/// Global variables: named doubles shared by the whole simulation. Add them in
/// main before use; any kernel may read them, but only main, init kernels and
/// void kernels may set them (a per-particle kernel
/// writing one would race with itself). Using a name never added is an error.
void add_variable(const std::string &name, double initial,
                  CallSite loc = CallSite::current());
double get_variable(const std::string &name,
                    CallSite loc = CallSite::current());
void set_variable(const std::string &name, double value,
                  CallSite loc = CallSite::current());

/// Simulated time (docs/semantics.md, "Simulated time"). The time starts at 0;
/// after every iteration the runtime adds the time step to it. The time step
/// starts at 0 and keeps its value until set: by main, init kernels or void
/// kernels (not per-particle kernels, which run once per particle), or by a
/// reduction kernel whose variable is "time_step". Any kernel may read both.
/// A time step must be finite and not negative.
double get_time();
double get_time_step();
void set_time_step(double dt, CallSite loc = CallSite::current());
/// The run stops after the iteration at whose end the time reaches `time`
/// (the --end-time option overrides it); get_end_time() is +inf when neither
/// set one, so a kernel may shorten the last step to end exactly there:
/// set_time_step(std::min(dt, get_end_time() - get_time())).
void set_end_time(double time, CallSite loc = CallSite::current());
double get_end_time();

/// The simulation box [lo, hi) and, per axis, whether it is periodic. On a
/// periodic axis positions wrap into [lo, hi) and neighbours are found across
/// the faces (a neighbour's get_pos() is then its nearest image); the box must
/// be longer than twice the influence radius there. On other axes the bounds are
/// not enforced: kernels keep particles in (walls are physics).
/// (lo and hi are given as x, y[, z] lists; see docs/semantics.md.)
void set_bounding_box(const std::vector<double> &lo, const std::vector<double> &hi,
                      const std::vector<bool> &periodic,
                      CallSite loc = CallSite::current());

} // namespace wash
