//===- wash/backend/backend.hpp - what every backend type provides -*- C++ -*-===//
//
// A backend is one C++ type, `wash::<name>::Backend<D>`, and the translator
// emits one driver against it (docs/architecture.md, "Adding a backend"). The
// driver owns the columns (the generated `Particles P`); the backend owns
// which rows are this process's real particles, the cell grid and whatever it
// keeps across a neighbour search (periodic images, MPI halos), and decides
// how a particle loop runs. ParticleBackend states that interface, so that a
// backend missing a piece fails here, in its unit test, not in generated code.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/cell_grid.hpp>
#include <wash/backend/columns.hpp>
#include <wash/backend/run.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/detail/box.hpp>
#include <wash/detail/frame.hpp>
#include <wash/detail/reduction.hpp>
#include <wash/vec.hpp>

#include <concepts>
#include <cstdint>
#include <vector>

namespace wash::backend {

/// The smallest column set a backend works on: what every generated
/// `Particles` has (id and pos), visited by forEachColumn.
template <int D> struct MinimalParticles {
  Column<std::uint64_t> id;
  Column<Vec<double, D>> pos;
  std::size_t size() const { return id.size(); }
  template <typename F> void forEachColumn(F f) {
    f(id);
    f(pos);
  }
};

/// A visitor of the columns a search or a refresh must carry to the copies
/// neighbours read (images, halo copies): calls its argument on each.
struct NoColumns {
  template <typename F> void operator()(F) const {}
};

/// The particle loops of a backend type `Derived`, over its owned() rows,
/// with `Loop`'s forEachParticle and forEachParticleChecked.
template <typename Derived, typename Loop> class ParticleLoops {
public:
  template <typename Body> void forEachParticle(Body body) const {
    Loop::forEachParticle(self().owned(), body);
  }
  template <typename Body> bool forEachParticleChecked(Body body) const {
    return Loop::forEachParticleChecked(self().owned(), body);
  }
  /// The same loops over some of the real particles' rows (one particle type's).
  template <typename Body> void forEachParticleIn(const std::vector<Index> &rows, Body body) const {
    Loop::forEachParticle(rows, body);
  }
  template <typename Body>
  bool forEachParticleCheckedIn(const std::vector<Index> &rows, Body body) const {
    return Loop::forEachParticleChecked(rows, body);
  }

private:
  const Derived &self() const { return static_cast<const Derived &>(*this); }
};

template <typename B, int D = B::dimensions>
concept ParticleBackend =
    requires(B b, const B cb, MinimalParticles<D> &P, const SearchGeometry &at,
             const detail::Box &box, const std::vector<double> &values, detail::Frame frame,
             const Run &run) {
      { B::name } -> std::convertible_to<const char *>;
      /// Whether this process prints and writes files (rank 0 of an MPI job).
      { cb.writes() } -> std::same_as<bool>;
      /// The rows of this process's real particles, ascending.
      { cb.owned() } -> std::same_as<const std::vector<Index> &>;
      /// The cell grid of the current search (what neighbour lists walk).
      { cb.grid() } -> std::same_as<const CellGrid<D> &>;
      /// create_particle, before it appends a row to every column: returns
      /// the new particle's id, its creation index over all processes. A
      /// distributed backend stores only its share: the row of a particle it
      /// does not keep takes the init kernel's writes and is gone by the next
      /// call (or distribute), so the columns hold the share plus one row.
      {
        b.create(P, 1.0, 1.0, 1.0, Vec<double, D>{}, Vec<double, D>{})
      } -> std::same_as<std::uint64_t>;
      /// After the init kernels: keeps this process's share of the particles
      /// and returns how many there are in all. The callable gives the cell
      /// size of a domain decomposition; only a distributed backend calls it.
      {
        b.distribute(P, [] { return 1.0; })
      } -> std::same_as<std::uint64_t>;
      /// A new neighbour search: images, halos, the cell sort of every column.
      b.search(P, at, box, NoColumns{});
      /// Brings the copies neighbours read up to date for the columns visited.
      b.refresh(NoColumns{});
      /// Calls body(row) for every real particle; the checked form's body
      /// returns whether what it wrote is finite, and so does the loop.
      cb.forEachParticle([](Index) {});
      {
        cb.forEachParticleChecked([](Index) { return true; })
      } -> std::same_as<bool>;
      /// A reduction of values[row] over every real particle: a Sum exact and
      /// rounded once (detail::ExactSum), Min and Max (docs/semantics.md).
      { cb.reduce(P.id, values, detail::ReduceOp::Sum) } -> std::same_as<double>;
      /// The same over some of the real particles' rows (one particle type's).
      { cb.reduceOver(cb.owned(), P.id, values, detail::ReduceOp::Min) } -> std::same_as<double>;
      /// Combines this process's largest search radius with the others'.
      { B::combineMax(1.0) } -> std::same_as<double>;
      /// The frame of every particle, for the writing process.
      { cb.gather(frame) } -> std::same_as<detail::Frame>;
      /// The backend's own lines of the end-of-run summary.
      cb.report(run);
      /// Checkpoints (checkpoint.hpp): this process's shard number and the
      /// count, collectives over the processes, and after a restart the
      /// particles read moved to their owners (returns how many in all).
      { cb.rankIndex() } -> std::same_as<int>;
      { cb.rankCount() } -> std::same_as<int>;
      cb.barrier();
      { cb.anyRank(true) } -> std::same_as<bool>;
      { cb.sumOverRanks(std::uint64_t(1)) } -> std::same_as<std::uint64_t>;
      {
        b.restore(P, [] { return 1.0; })
      } -> std::same_as<std::uint64_t>;
    };

} // namespace wash::backend
