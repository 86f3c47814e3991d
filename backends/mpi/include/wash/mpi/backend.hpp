//===- wash/mpi/backend.hpp - the MPI backend type ----------------*- C++ -*-===//
//
// Each rank owns the particles of its cells (domain.hpp) and, while a search
// lasts, halo copies of other ranks' particles within reach (halo.hpp); the
// particle loop is the OpenMP one, timed for the load balance.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/backend.hpp>
#include <wash/backend/cell_grid.hpp>
#include <wash/backend/run.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/mpi/creations.hpp>
#include <wash/mpi/domain.hpp>
#include <wash/mpi/for_each.hpp>
#include <wash/mpi/halo.hpp>

#include <string>

namespace wash::mpi {

template <int D> class Backend : public backend::ParticleLoops<Backend<D>, Loop> {
public:
  static constexpr int dimensions = D;
  static constexpr const char *name = "mpi";

  bool writes() const { return rank() == 0; }
  const std::vector<Index> &owned() const { return halo_.owned; }
  const backend::CellGrid<D> &grid() const { return grid_; }

  /// create_particle, before it appends a row: the new particle's id (its
  /// creation index). Every rank runs the init kernels; each stores only its
  /// blocks of creation indices (creations.hpp), the rest in a scratch row.
  template <typename Particles, typename V>
  std::uint64_t create(Particles &P, double density, double mass, double smoothingLength,
                       const V &pos, const V &vel) {
    return creations_.create(P, density, mass, smoothingLength, pos, vel);
  }

  /// After the init kernels: checks that every rank created the same
  /// particles, then moves each rank's to their owners, on a domain whose
  /// cells are cellSize() wide.
  template <typename Particles, typename CellSize>
  std::uint64_t distribute(Particles &P, CellSize cellSize) {
    creations_.finish(P);
    return settle(P, cellSize);
  }

  /// Particles to their owners, images across periodic faces, a new halo
  /// carrying the columns `fields` visits (id and pos among them), then
  /// everything local sorted by (cell, id). Migration moves every column.
  /// `h(row)`, where the rule reads smoothing lengths, lets images and the
  /// halo reach only as far as each particle's pairs do (pair_reach.hpp).
  /// With backend::HaloColumns, rows kept from the previous halo receive
  /// only its `kept` columns (halo_history.hpp); otherwise every row receives
  /// every column `fields` visits.
  template <typename Particles, typename Fields,
            typename SmoothingLength = backend::NoSmoothingLength>
  void search(Particles &P, const backend::SearchGeometry &at, const ::wash::detail::Box &box,
              Fields fields, SmoothingLength h = {}) {
    const ::wash::detail::ProfileScope profiled("neighbour search");
    if constexpr (requires { fields.kept; }) {
      const auto carried = carriedColumns(fields.kept, fields.fresh);
      stashHalo(P, halo_.recv, history_, carried);
      newSearch(P, at, box, fields.kept, carried, h);
    } else {
      history_.forget();
      const auto nothing = [](auto) {};
      newSearch(P, at, box, fields, nothing, h);
    }
  }

  /// Local images, then the halo copies of the columns `fields` visits.
  template <typename Fields> void refresh(Fields fields) {
    const ::wash::detail::ProfileScope profiled("halo exchange (MPI)");
    exchange(halo_, fields);
  }

  /// Collective. A Sum adds every rank's exact sum (a fixed-size
  /// MPI_Allreduce, whatever the particle count); Min and Max reduce locally.
  double reduce(const backend::Column<std::uint64_t> &, const std::vector<double> &values,
                ::wash::detail::ReduceOp op) const {
    if (op == ::wash::detail::ReduceOp::Sum)
      return allreduceSum(Loop::sum(values, halo_.owned)).round<double>();
    return allreduceMinMax(values, halo_.owned, op);
  }
  /// The same over `rows` of this rank only (one particle type's).
  double reduceOver(const std::vector<Index> &rows, const backend::Column<std::uint64_t> &,
                    const std::vector<double> &values, ::wash::detail::ReduceOp op) const {
    if (op == ::wash::detail::ReduceOp::Sum)
      return allreduceSum(Loop::sum(values, rows)).round<double>();
    return allreduceMinMax(values, rows, op);
  }
  static double combineMax(double v) { return allreduceMax(v); }
  /// A frame stays on its rank: the run's output writes every rank's rows
  /// collectively (detail::processes(), set by the entry point), through rank
  /// 0 in bounded chunks for CSV and VTK, by each rank itself for HDF5.
  ::wash::detail::Frame gather(::wash::detail::Frame local) const { return local; }

  // Checkpoint and restart (wash/backend/checkpoint.hpp): collective.
  int rankIndex() const { return rank(); }
  int rankCount() const { return ranks(); }
  void barrier() const { allreduceSum(std::uint64_t(0)); }
  bool anyRank(bool flag) const { return allreduceMax(std::uint64_t(flag)) != 0; }
  std::uint64_t sumOverRanks(std::uint64_t v) const { return allreduceSum(v); }
  /// The particles this rank read from a checkpoint (any share) go to their
  /// owners, as after the init kernels.
  template <typename Particles, typename CellSize>
  std::uint64_t restore(Particles &P, CellSize cellSize) {
    return settle(P, cellSize);
  }

  /// Collective: the traffic of the run, per step, over all ranks and from
  /// the busiest rank; at the start, the most particles one rank held while
  /// the init kernels ran and the most bytes one rank sent to distribute them;
  /// the halo copies of the last search, in all and on the busiest rank.
  void report(const backend::Run &run) const {
    const std::uint64_t steps = run.steps() ? run.steps() : 1;
    const Traffic &sent = traffic();
    const std::uint64_t haloBytes = allreduceSum(sent.halo);
    const std::uint64_t moveBytes = allreduceSum(sent.migration);
    const std::uint64_t sumBytes = allreduceSum(sent.sums);
    const std::uint64_t busiest = allreduceMax(sent.halo + sent.migration + sent.sums);
    const std::uint64_t initRows = allreduceMax(creations_.mostRows());
    const std::uint64_t startBytes = allreduceMax(startBytes_);
    const std::uint64_t copies = allreduceSum(std::uint64_t(halo_.ghosts));
    const std::uint64_t mostCopies = allreduceMax(std::uint64_t(halo_.ghosts));
    run.report("wash mpi: " + std::to_string(ranks()) + " ranks; halo exchange " +
               std::to_string(haloBytes / steps) + " bytes/step, particle migration " +
               std::to_string(moveBytes / steps) + " bytes/step, sum reductions " +
               std::to_string(sumBytes / steps) + " bytes/step (all ranks)");
    run.report("wash mpi: at most " + std::to_string(busiest / steps) +
               " bytes/step sent by one rank; at start at most " + std::to_string(initRows) +
               " particles held and " + std::to_string(startBytes) +
               " bytes sent by one rank; halo of the last search " + std::to_string(copies) +
               " copies, at most " + std::to_string(mostCopies) + " on one rank");
  }

private:
  template <typename Particles, typename Fields, typename Carried, typename SmoothingLength>
  void newSearch(Particles &P, const backend::SearchGeometry &at, const ::wash::detail::Box &box,
                 Fields fields, Carried carried, SmoothingLength h) {
    {
      const ::wash::detail::ProfileScope migration("particle migration (MPI)");
      redistribute(P, domain_, halo_);
    }
    const RowReach<SmoothingLength> reachOf{at, h};
    backend::addImages<D>(P, halo_.owned, box, reachOf, halo_, &combineMax);
    {
      const ::wash::detail::ProfileScope exchange("halo exchange (MPI)");
      buildHalo(P, domain_, reachOf, box, halo_, fields, carried, history_);
    }
    grid_.sort(P.pos, P.id, at.cellSize, order_);
    P.forEachColumn([this](auto &column) { backend::permute(column, order_); });
    halo_.permuted(order_);
  }

  /// Collective: the particles this rank holds (any share) go to their owners,
  /// on a domain balanced by a sample of every rank's cells; returns how many
  /// there are in all.
  template <typename Particles, typename CellSize>
  std::uint64_t settle(Particles &P, CellSize cellSize) {
    halo_.ownAll(P.size());
    history_.forget();
    // cellSize() sees this rank's particles only: the largest over the ranks
    // that have some.
    const double largest = allreduceMax(P.size() ? cellSize() : 0.0);
    domain_.setCellSize(largest > 0.0 ? largest : 1.0);
    const typename Domain<D>::Cell lowest = lowestCell(P);
    domain_.setLowestCell(lowest);
    std::vector<typename Domain<D>::Cell> cells(P.size());
    for (Index i = 0; i < P.size(); ++i)
      cells[i] = startCell(P.pos[i], lowest);
    domain_.balance(cells, double(P.size()));
    // Counted apart from the steps' migration: it happens once.
    const std::uint64_t before = traffic().migration;
    migrate(P, domain_, halo_);
    startBytes_ = traffic().migration - before;
    traffic().migration = before;
    return allreduceSum(std::uint64_t(halo_.owned.size()));
  }

  /// The cell that places a particle on the domain at the start: its
  /// position's wrapped into the box on periodic axes (the generated code
  /// wraps what the init kernels created only after distribute), and, on an
  /// axis where it is not finite, `lowest` (the finite checks after
  /// distribute name it, as on every backend).
  template <typename PosT>
  typename Domain<D>::Cell startCell(const PosT &pos,
                                     const typename Domain<D>::Cell &lowest) const {
    const ::wash::detail::Box &box = ::wash::detail::runSettings().box;
    Vec<double, D> p(pos);
    for (int a = 0; a < D; ++a)
      if (box.defined && box.periodic[a] && std::isfinite(p.at(a)))
        *p[a] = box.wrap(p.at(a), a);
    typename Domain<D>::Cell c = domain_.cellOf(p);
    for (int a = 0; a < D; ++a)
      if (!std::isfinite(p.at(a)))
        c[a] = lowest[a];
    return c;
  }

  /// Collective: the lowest start cell coordinate of any rank's particles, by
  /// axis (non-finite coordinates left out).
  template <typename Particles> typename Domain<D>::Cell lowestCell(const Particles &P) const {
    constexpr std::int64_t shift = std::int64_t(1) << 62; // cells to unsigned, order kept
    typename Domain<D>::Cell lowest;
    for (int a = 0; a < D; ++a) {
      std::uint64_t mine = ~std::uint64_t(0);
      for (Index i = 0; i < P.size(); ++i) {
        if (!std::isfinite(double(P.pos[i].at(a))))
          continue;
        const std::int64_t c =
            std::clamp<std::int64_t>(startCell(P.pos[i], {})[a], -shift, shift - 1);
        mine = std::min(mine, std::uint64_t(c + shift));
      }
      const std::uint64_t all = allreduceMin(mine);
      lowest[a] = all == ~std::uint64_t(0) ? 0 : std::int64_t(all) - shift;
    }
    return lowest;
  }

  Creations creations_;
  std::uint64_t startBytes_ = 0; ///< sent by the migration of distribute or restore
  backend::CellGrid<D> grid_;
  std::vector<Index> order_;
  Domain<D> domain_;
  HaloPlan halo_;
  HaloHistory history_;
};

} // namespace wash::mpi
