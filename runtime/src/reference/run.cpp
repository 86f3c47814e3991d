//===- run.cpp - wash::start() of the reference runtime ----------------===//
//
// The definition of what a wash program computes: init kernels once, then each
// iteration every kernel in registration order, one particle at a time. A force
// kernel's neighbours are handles into a snapshot taken when the kernel starts,
// listed in the canonical order of neighbour_search.hpp. The set-up, output
// and checks around the kernels are every runtime's (wash/detail/run.hpp).
//
//===----------------------------------------------------------------------===//
#include "checkpoint.hpp"
#include "state.hpp"

#include <wash/detail/neighbour_search.hpp>
#include <wash/detail/reduction.hpp>
#include <wash/detail/run.hpp>
#include <wash/detail/search.hpp>
#include <wash/detail/sim_time.hpp>

#include <new>

namespace wash {

using detail::Kernel;
using detail::RunError;
using detail::runSettings;
using detail::state;

namespace {

/// The bytes of one particle in `store`, every column counted.
std::size_t storeBytes(const detail::ParticleStore &store) {
  return sizeof(std::uint64_t) + 3 * sizeof(ParticleVec) + 3 * sizeof(double) +
         sizeof(std::uint32_t) +
         store.scalars.size() * sizeof(double) + store.vectors.size() * sizeof(ParticleVec);
}

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

/// Whether particle i of `store` is of kernel type t (-1: every type).
bool ofType(const detail::ParticleStore &store, std::size_t i, int t) {
  return t < 0 || store.type[i] == std::uint32_t(t);
}

/// Particle i's neighbours are those of the canonical list that are of the
/// kernel's neighbour type, in the same order (docs/semantics.md).
void runForceKernel(ForceKernel kernel, const Kernel &k, detail::ParticleStore &live,
                    const detail::SearchRule &rule, const detail::Box &box,
                    const std::string &where) {
  detail::ParticleStore snapshot;
  detail::CellList<dimensions> cells;
  try {
    const detail::ProfileScope profiled("neighbour search (snapshot, cell list)");
    snapshot = live;
    cells.build(snapshot.pos, snapshot.id, cellSize(rule, snapshot, box, where));
  } catch (const std::bad_alloc &) {
    snapshot = {}; // room for the message
    cells = {};
    throw detail::outOfMemory("the neighbours' snapshot and cell list (" +
                                  where.substr(0, where.size() - 2) + ")",
                              live.size(), storeBytes(live));
  }
  snapshot.neighbours = true;
  std::vector<std::size_t> indices;
  std::vector<ParticleVec> images;
  std::vector<Particle> neighbours;
  // The symmetric rule: every particle within the largest radius (the cell
  // size), then those within the pair radius.
  const bool symmetric = rule.perParticle() && rule.symmetric;
  const double largest = symmetric ? cells.cellSize() : 0.0;
  for (std::size_t i = 0; i < live.size(); ++i) {
    if (!ofType(live, i, k.type))
      continue;
    const double radius = symmetric ? largest : searchRadius(rule, snapshot, i);
    if (box.anyPeriodic())
      cells.periodicNeighbours(i, radius, rule.perParticle(), box, indices, images,
                               [](double v) { return state().store(v); });
    else
      cells.neighbours(i, radius, rule.perParticle(), indices);
    neighbours.clear();
    for (std::size_t n = 0; n < indices.size(); ++n) { // const: read-only
      const std::size_t j = indices[n];
      if (symmetric &&
          !detail::withinRadius<dimensions>(
              snapshot.pos[i], box.anyPeriodic() ? images[n] : snapshot.pos[j],
              detail::pairRadius(searchRadius(rule, snapshot, i), searchRadius(rule, snapshot, j))))
        continue;
      if (ofType(snapshot, j, k.neighbourType))
        neighbours.emplace_back(&snapshot, j, box.anyPeriodic() ? &images[n] : nullptr);
    }
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
    s.inInitKernel = s.typesSettable = true;
    reinterpret_cast<InitKernel>(k.function)();
    s.inInitKernel = s.typesSettable = false;
    break;
  case Kernel::Update:
    s.typesSettable = true;
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      if (!ofType(s.particles, i, k.type))
        continue;
      Particle self(&s.particles, i);
      reinterpret_cast<UpdateKernel>(k.function)(self);
    }
    s.typesSettable = false;
    break;
  case Kernel::Void:
    s.inVoidKernel = true;
    reinterpret_cast<VoidKernel>(k.function)();
    s.inVoidKernel = false;
    break;
  case Kernel::ReductionKind: {
    std::vector<double> values; // storage order is id order in the reference
    for (std::size_t i = 0; i < s.particles.size(); ++i)
      if (ofType(s.particles, i, k.type))
        values.push_back(reinterpret_cast<ReductionKernel>(k.function)(Particle(&s.particles, i)));
    const double reduced = detail::reduceInIdOrder(values, detail::ReduceOp(k.reduceOp));
    if (k.variable == detail::timeStepTarget)
      detail::setReducedTimeStep(reduced);
    else
      set_variable(k.variable, reduced);
    break;
  }
  case Kernel::ForceKind:
    runForceKernel(reinterpret_cast<ForceKernel>(k.function), k, s.particles, runSettings().search,
                   runSettings().box,
                   "step " + std::to_string(step) + ": kernel '" + k.name + "': ");
    break;
  }
  wrapPositions(s, runSettings().box);
}

} // namespace

// Unlike generated programs' (where the translator checks it), this one
// checks that it is called from a void kernel.
void stop(CallSite loc) {
  if (!state().inVoidKernel)
    detail::usageError(loc, "wash::stop() can only be called from a void kernel");
  runSettings().stopRequested = true;
}

void start() {
  auto &s = state();
  if (s.started)
    throw RunError("start() was called twice");
  s.started = true;
  // Not translated: whatever precision and neighbour rule main asked for.
  detail::Run run(detail::Translation{.backend = "reference",
                                      .dimensions = dimensions,
                                      .floatStorage = std::nullopt,
                                      .smoothingLengthSearch = std::nullopt,
                                      .symmetricSupport = std::nullopt,
                                      .program = detail::referenceProgram(s)},
                  /*writes=*/true);
  // The reference checks every value after every kernel on a frame of the state.
  auto frame = [&s] {
    try {
      return s.frame(s.particles);
    } catch (const std::bad_alloc &) {
      throw detail::outOfMemory("a frame of the state (output and finiteness checks)",
                                s.particles.size(), storeBytes(s.particles));
    }
  };
  if (run.restarting()) { // the store and the run's state from a checkpoint
    detail::restoreCheckpoint(run, s);
  } else {
    for (const Kernel &k : s.kernels)
      if (k.kind == Kernel::Init) {
        runKernel(k, s, 0);
        run.checkFinite(frame(), 0, k.name);
      }
    run.begin(s.particles.size(), frame);
  }
  for (std::uint64_t step = run.firstStep(); step <= run.steps(); ++step) {
    for (const Kernel &k : s.kernels)
      if (k.kind != Kernel::Init) {
        run.kernel(k.name.c_str());
        runKernel(k, s, step);
        run.checkFinite(frame(), step, k.name);
      }
    run.endStep(step, frame); // after wash::stop(), run.steps() is this step
    detail::checkpointAfterStep(run, s, step);
  }
  run.finish(frame());
}

} // namespace wash
