//===- wash/backend/shared_memory.hpp - one process holds every particle -*- C++ -*-===//
//
// The serial and OpenMP backends: every particle is in this process, periodic
// images are local copies (periodic.hpp), and the particle loop is the only
// difference between them (`Loop`, from wash/serial or wash/openmp).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/backend.hpp>
#include <wash/backend/cell_grid.hpp>
#include <wash/backend/columns.hpp>
#include <wash/backend/periodic.hpp>
#include <wash/backend/reduce.hpp>
#include <wash/backend/run.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/detail/frame.hpp>
#include <wash/detail/profile.hpp>

#include <cstdint>
#include <vector>

namespace wash::backend {

template <int D, typename Loop>
class SharedMemoryBackend : public ParticleLoops<SharedMemoryBackend<D, Loop>, Loop> {
public:
  static constexpr int dimensions = D;
  static constexpr const char *name = Loop::name;

  bool writes() const { return true; }
  const std::vector<Index> &owned() const { return images_.owned; }
  const CellGrid<D> &grid() const { return grid_; }

  /// create_particle, before it appends a row: the id, the creation index.
  template <typename Particles, typename V>
  std::uint64_t create(Particles &P, double, double, double, const V &, const V &) {
    return P.size();
  }

  /// Every particle the init kernels created is real and stays here.
  template <typename Particles, typename CellSize>
  std::uint64_t distribute(Particles &P, CellSize) {
    images_.ownAll(P.size());
    return P.size();
  }

  /// Images across periodic faces, then every particle sorted by (cell, id)
  /// (docs/semantics.md). Images are copies of every column, so the visited
  /// columns need no transfer. Columns the generated program marks as
  /// rewritten before they are read (forEachReorderedColumn) keep their order.
  /// `h(row)`, where the rule reads smoothing lengths, lets images reach
  /// only as far as each particle's pairs do.
  template <typename Particles, typename Fields, typename SmoothingLength = NoSmoothingLength>
  void search(Particles &P, const SearchGeometry &at, const detail::Box &box, Fields,
              SmoothingLength h = {}) {
    const detail::ProfileScope profiled("neighbour search");
    dropImages(P, images_);
    addImages<D>(P, images_.owned, box, RowReach<SmoothingLength>{at, h}, images_);
    grid_.sort(P.pos, P.id, at.cellSize, order_);
    auto reorder = [this](auto &column) { permute(column, order_); };
    if constexpr (requires { P.forEachReorderedColumn(reorder); })
      P.forEachReorderedColumn(reorder);
    else
      P.forEachColumn(reorder);
    images_.permuted(order_);
  }

  template <typename Fields> void refresh(Fields fields) {
    const detail::ProfileScope profiled("periodic images refresh");
    refreshImages(images_, fields);
  }

  /// A Sum is exact (the loop's per-thread sums, merged); Min and Max go by id.
  double reduce(const Column<std::uint64_t> &ids, const std::vector<double> &values,
                detail::ReduceOp op) const {
    if (op == detail::ReduceOp::Sum)
      return Loop::sum(values, images_.owned).template round<double>();
    return reduceById(ids, values, images_.owned, op);
  }
  /// The same over `rows` only (one particle type's).
  double reduceOver(const std::vector<Index> &rows, const Column<std::uint64_t> &ids,
                    const std::vector<double> &values, detail::ReduceOp op) const {
    if (op == detail::ReduceOp::Sum)
      return Loop::sum(values, rows).template round<double>();
    return reduceRowsById(ids, values, rows, op);
  }
  static double combineMax(double v) { return v; }

  // Checkpoint and restart (wash/backend/checkpoint.hpp): one process.
  int rankIndex() const { return 0; }
  int rankCount() const { return 1; }
  void barrier() const {}
  bool anyRank(bool flag) const { return flag; }
  std::uint64_t sumOverRanks(std::uint64_t v) const { return v; }
  /// The particles read from a checkpoint are all real.
  template <typename Particles, typename CellSize> std::uint64_t restore(Particles &P, CellSize) {
    images_.ownAll(P.size());
    return P.size();
  }
  detail::Frame gather(detail::Frame local) const { return local; }
  void report(const Run &) const {}

private:
  CellGrid<D> grid_;
  std::vector<Index> order_;
  Images images_; // real particles, and periodic images
};

} // namespace wash::backend
