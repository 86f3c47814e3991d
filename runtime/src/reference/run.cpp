//===- run.cpp - wash::start() of the reference runtime ----------------===//
//
// The definition of what a wash program computes: init kernels once, then each
// iteration every kernel in registration order, one particle at a time. A force
// kernel's neighbours are handles into a snapshot taken when the kernel starts,
// listed in the canonical order of neighbour_search.hpp.
//
//===----------------------------------------------------------------------===//
#include "state.hpp"

#include <wash/detail/neighbour_search.hpp>
#include <wash/detail/progress.hpp>
#include <wash/detail/reduction.hpp>
#include <wash/detail/run_settings.hpp>
#include <wash/detail/search.hpp>

#include <cstdio>
#include <iostream>

namespace wash {

using detail::Kernel;
using detail::RunError;
using detail::runSettings;
using detail::state;

namespace {

/// Particle i's search radius: the influence radius, or its support radius.
double searchRadius(const detail::SearchRule &rule, const detail::ParticleStore &snapshot,
                    std::size_t i) {
  return rule.perParticle() ? detail::supportRadius(*rule.support, snapshot.smoothingLength[i])
                            : *rule.radius;
}

/// The cell size of a search: the influence radius, or the largest support
/// radius (checked against the box, as the smoothing lengths may have grown).
double cellSize(const detail::SearchRule &rule, const detail::ParticleStore &snapshot,
                const detail::Box &box, const std::string &where) {
  if (!rule.perParticle())
    return *rule.radius;
  double largest = 0.0;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    if (std::string bad = detail::checkSmoothingLength(snapshot.smoothingLength[i]); !bad.empty())
      throw RunError(where + "particle " + std::to_string(snapshot.id[i]) + ": " + bad);
    largest = std::max(largest, searchRadius(rule, snapshot, i));
  }
  if (std::string bad = detail::checkPeriodicSupport(box, dimensions, largest); !bad.empty())
    throw RunError(where + bad);
  return largest > 0.0 ? largest : 1.0; // any cell size finds coincident particles
}

void runForceKernel(ForceKernel kernel, detail::ParticleStore &live, const detail::SearchRule &rule,
                    const detail::Box &box, const std::string &where) {
  detail::ParticleStore snapshot = live;
  detail::CellList<dimensions> cells;
  cells.build(snapshot.pos, snapshot.id, cellSize(rule, snapshot, box, where));
  std::vector<std::size_t> indices;
  std::vector<ParticleVec> images;
  std::vector<Particle> neighbours;
  for (std::size_t i = 0; i < live.size(); ++i) {
    const double radius = searchRadius(rule, snapshot, i);
    if (box.anyPeriodic())
      cells.periodicNeighbours(i, radius, rule.perParticle(), box, indices, images,
                               [](double v) { return state().store(v); });
    else
      cells.neighbours(i, radius, rule.perParticle(), indices);
    neighbours.clear();
    for (std::size_t k = 0; k < indices.size(); ++k) // const: read-only
      neighbours.emplace_back(&snapshot, indices[k], box.anyPeriodic() ? &images[k] : nullptr);
    Particle self(&live, i);
    kernel(self, neighbours);
  }
}

/// On periodic axes, positions wrap into the box after every kernel.
void wrapPositions(detail::State &s, const detail::Box &box) {
  if (!box.anyPeriodic())
    return;
  for (ParticleVec &p : s.particles.pos)
    for (int a = 0; a < dimensions; ++a)
      if (box.periodic[a])
        *p[a] = s.store(box.wrap(p.at(a), a));
}

void runKernel(const Kernel &k, detail::State &s, std::uint64_t step) {
  switch (k.kind) {
  case Kernel::Init:
    s.inInitKernel = true;
    reinterpret_cast<InitKernel>(k.function)();
    s.inInitKernel = false;
    break;
  case Kernel::Update:
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      Particle self(&s.particles, i);
      reinterpret_cast<UpdateKernel>(k.function)(self);
    }
    break;
  case Kernel::Void:
    s.inVoidKernel = true;
    reinterpret_cast<VoidKernel>(k.function)();
    s.inVoidKernel = false;
    break;
  case Kernel::ReductionKind: {
    std::vector<double> values; // storage order is id order in the reference
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      values.push_back(reinterpret_cast<ReductionKernel>(k.function)(Particle(&s.particles, i)));
    set_variable(k.variable, detail::reduceInIdOrder(values, detail::ReduceOp(k.reduceOp)));
    break;
  }
  case Kernel::ForceKind:
    runForceKernel(reinterpret_cast<ForceKernel>(k.function), s.particles, runSettings().search,
                   runSettings().box,
                   "step " + std::to_string(step) + ": kernel '" + k.name + "': ");
    break;
  }
  wrapPositions(s, runSettings().box);
}

void checkFinite(const detail::State &s, std::uint64_t step, const Kernel &k) {
  std::string bad = detail::findNonFinite(s.frame(s.particles));
  if (!bad.empty())
    throw RunError("step " + std::to_string(step) + ": after kernel '" + k.name + "': " + bad);
}

} // namespace

// Unlike generated programs' (where the translator checks it), this one
// checks that it is called from a void kernel.
void stop(std::source_location loc) {
  if (!state().inVoidKernel)
    detail::usageError(loc, "wash::stop() can only be called from a void kernel");
  runSettings().stopRequested = true;
}

void start() {
  auto &s = state();
  const detail::RunSettings &settings = runSettings();
  const detail::RunOptions &options = detail::programOptions();
  if (s.started)
    throw RunError("start() was called twice");
  s.started = true;
  if (std::string bad = settings.search.check(); !bad.empty())
    throw RunError(bad);
  std::uint64_t steps = options.steps ? *options.steps : settings.maxIterations.value_or(0);
  if (!options.steps && !settings.maxIterations)
    throw RunError("no iteration count: call wash::set_max_iterations or pass --steps N");
  if (std::string bad =
          detail::checkBox(settings.box, dimensions, settings.search.radius.value_or(0.0));
      !bad.empty())
    throw RunError(bad);
  detail::RunOutput output(options, settings.outputBaseName());

  for (const Kernel &k : s.kernels)
    if (k.kind == Kernel::Init) {
      runKernel(k, s, 0);
      checkFinite(s, 0, k);
    }
  const bool talk = !options.quiet;
  if (talk)
    std::printf("wash reference: '%s', %zu particles, %dD, %s, %s, %llu steps\n",
                settings.simulationName.c_str(), s.particles.size(), dimensions,
                settings.useFloat.value_or(false) ? "float" : "double",
                settings.search.describe().c_str(), (unsigned long long)steps);
  std::fflush(stdout);
  if (output.frameDue(0, steps))
    output.writeFrame(0, s.frame(s.particles));

  detail::Progress progress(steps, s.particles.size(), talk);
  for (std::uint64_t step = 1; step <= steps; ++step) {
    for (const Kernel &k : s.kernels)
      if (k.kind != Kernel::Init) {
        runKernel(k, s, step);
        checkFinite(s, step, k);
      }
    if (settings.stopRequested)
      steps = step; // this step is the last: written as such
    if (output.frameDue(step, steps))
      output.writeFrame(step, s.frame(s.particles));
    progress.update(step);
  }
  double seconds = progress.finish();
  output.finish(s.frame(s.particles));
  if (talk)
    std::printf(
        "wash: %llu steps of %zu particles in %.2f s (%.3g particle-steps/s); output in %s\n",
        (unsigned long long)steps, s.particles.size(), seconds,
        seconds > 0 ? double(steps) * double(s.particles.size()) / seconds : 0.0,
        output.directory().c_str());
}

} // namespace wash
