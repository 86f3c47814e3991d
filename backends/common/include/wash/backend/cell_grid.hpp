//===- wash/backend/cell_grid.hpp - cell-sorted particles and neighbour ranges -*- C++ -*-===//
//
// The canonical neighbour order of docs/semantics.md, without sorting per
// particle: particles are kept sorted by (cell, id), cells in (z,) y, x order
// of a dense grid over the occupied cells, so the candidates of one row of the
// stencil are one contiguous index range, already in canonical order (for the
// influence-radius rule, where the cell size is the radius).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace wash::backend {

/// The candidates of one particle: contiguous index ranges, one per row of
/// cells; 4^(D-1) at most for a radius up to the cell size, 10^(D-1) for one
/// up to 4 cells (searchGeometry's bound for smoothing lengths).
struct CandidateRanges {
  static constexpr int capacity = 100;
  std::array<Index, capacity> begin, end;
  int count = 0;
};

template <int D> class CellGrid {
public:
  /// Sorts particles by (cell, id) for cells of side r: fills `order` (new[k] =
  /// old[order[k]]) and the cell table for the new order. Positions are read
  /// as double, whatever the storage precision.
  template <typename PosT>
  void sort(const Column<PosT> &pos, const Column<std::uint64_t> &id, double r,
            std::vector<Index> &order) {
    const std::size_t n = pos.size();
    if (n > std::numeric_limits<Index>::max())
      throw std::length_error("wash: more particles than the index type holds");
    radius_ = r;
    // Cell bounds from the extreme coordinates (the cell is monotone in them),
    // every axis in one pass.
    std::array<std::int64_t, D> lo{}, hi{};
    double least[D], most[D];
    for (int a = 0; a < D; ++a) {
      least[a] = std::numeric_limits<double>::infinity();
      most[a] = -least[a];
    }
    WASH_OMP(parallel for if(n >= parallelMinimum) schedule(static) reduction(min : least[:D]) \
             reduction(max : most[:D]))
    for (std::size_t p = 0; p < n; ++p)
      for (int a = 0; a < D; ++a) {
        least[a] = std::min(least[a], double(pos[p].at(a)));
        most[a] = std::max(most[a], double(pos[p].at(a)));
      }
    for (int a = 0; a < D && n > 0; ++a) {
      lo[a] = coordinate(least[a]);
      hi[a] = coordinate(most[a]);
    }
    std::size_t cells = 1;
    for (int a = 0; a < D; ++a) {
      lo_[a] = n ? lo[a] : 0;
      dims_[a] = n ? hi[a] - lo[a] + 1 : 1;
      cells *= std::size_t(dims_[a]);
    }
    if (cells > std::numeric_limits<Index>::max())
      throw std::length_error("wash: the particles span more cells than the grid can index; "
                              "is a particle far outside the others?");
    cell_.resize(n);
    WASH_OMP(parallel for if(n >= parallelMinimum) schedule(static))
    for (std::size_t p = 0; p < n; ++p) {
      std::array<std::int64_t, D> c;
      for (int a = 0; a < D; ++a)
        c[a] = coordinate(double(pos[p].at(a)));
      cell_[p] = Index(linear(c));
    }
    // Counting sort by cell (stable), then ids ascending inside each cell.
    cellStart_.assign(cells + 1, 0);
    for (std::size_t p = 0; p < n; ++p)
      ++cellStart_[cell_[p] + 1];
    for (std::size_t c = 0; c < cells; ++c)
      cellStart_[c + 1] += cellStart_[c];
    order.resize(n);
    next_.assign(cellStart_.begin(), cellStart_.end() - 1);
    for (std::size_t p = 0; p < n; ++p)
      order[next_[cell_[p]]++] = Index(p);
    // Ids ascending inside each cell. A cell's particles arrive as a few runs
    // already in id order (one per cell they were in before), a handful in
    // all: insertion sort.
    WASH_OMP(parallel for if(n >= parallelMinimum) schedule(dynamic, 256))
    for (std::size_t c = 0; c < cells; ++c) {
      const Index b = cellStart_[c], e = cellStart_[c + 1];
      for (Index k = b + 1; k < e; ++k) {
        const Index moving = order[k];
        const std::uint64_t key = id[moving];
        Index to = k;
        for (; to > b && id[order[to - 1]] > key; --to)
          order[to] = order[to - 1];
        order[to] = moving;
      }
    }
  }

  /// Candidate ranges for a particle at p: the cells overlapping [p - r, p + r]
  /// on each axis, in canonical order (the reference's cell set exactly), for a
  /// search radius r of at most 4 cells.
  void candidates(const Vec<double, D> &p, double r, CandidateRanges &out) const {
    std::array<std::int64_t, D> from, to;
    for (int a = 0; a < D; ++a) {
      from[a] = std::max(coordinate(p.at(a) - r), lo_[a]);
      to[a] = std::min(coordinate(p.at(a) + r), lo_[a] + dims_[a] - 1);
    }
    out.count = 0;
    if constexpr (D == 2) {
      for (std::int64_t y = from[1]; y <= to[1]; ++y)
        addRow(out, {from[0], y}, to[0]);
    } else {
      for (std::int64_t z = from[2]; z <= to[2]; ++z)
        for (std::int64_t y = from[1]; y <= to[1]; ++y)
          addRow(out, {from[0], y, z}, to[0]);
    }
  }

  double radius() const { return radius_; }

private:
  std::int64_t coordinate(double x) const {
    return static_cast<std::int64_t>(std::floor(x / radius_));
  }
  std::size_t linear(const std::array<std::int64_t, D> &c) const {
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a)
      index = index * std::size_t(dims_[a]) + std::size_t(c[a] - lo_[a]);
    return index;
  }
  void addRow(CandidateRanges &out, std::array<std::int64_t, D> first, std::int64_t lastX) const {
    if (first[0] > lastX)
      return;
    std::size_t start = linear(first);
    Index b = cellStart_[start], e = cellStart_[start + std::size_t(lastX - first[0]) + 1];
    if (b < e) {
      if (out.count == CandidateRanges::capacity)
        throw std::length_error("wash: a search radius spans too many cells");
      out.begin[out.count] = b;
      out.end[out.count] = e;
      ++out.count;
    }
  }

  double radius_ = 1.0;
  std::array<std::int64_t, D> lo_{}, dims_{};
  std::vector<Index> cellStart_, cell_, next_;
};

} // namespace wash::backend
