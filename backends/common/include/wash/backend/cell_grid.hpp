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
#include <wash/detail/cell.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace wash::backend {

/// The candidates of one particle: contiguous index ranges, one per row of
/// cells; 4^(D-1) at most for a radius up to the cell size, 10^(D-1) for one
/// up to 4 cells (searchGeometry's bound for smoothing lengths).
struct CandidateRanges {
  static constexpr int capacity = 100;
  std::array<Index, capacity> begin, end;
  int count = 0;
  std::size_t total = 0; ///< candidates in all ranges
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
    inverse_ = 1.0 / r;
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
    double span = 1.0; // as a double: the product may not fit an integer
    for (int a = 0; a < D; ++a) {
      lo_[a] = n ? lo[a] : 0;
      dims_[a] = n ? hi[a] - lo[a] + 1 : 1;
      span *= n ? double(hi[a]) - double(lo[a]) + 1.0 : 1.0;
    }
    if (!(span <= double(std::numeric_limits<Index>::max())))
      throw std::length_error(tooManyCells(span, r));
    const std::size_t cells = std::size_t(span);
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
  /// search radius r of at most 4 cells. Runs once per particle and scan, so
  /// it keeps its count in a local and sums the candidates as it goes.
  void candidates(const Vec<double, D> &p, double r, CandidateRanges &out) const {
    std::array<std::int64_t, D> from, to;
    for (int a = 0; a < D; ++a) {
      std::int64_t first, last;
      if (!neighbourCells(p.at(a), r, first, last)) {
        first = coordinate(p.at(a) - r);
        last = coordinate(p.at(a) + r);
      }
      from[a] = std::max(first, lo_[a]);
      to[a] = std::min(last, lo_[a] + dims_[a] - 1);
    }
    int count = 0;
    std::size_t total = 0;
    const std::size_t rowCells = std::size_t(to[0] - from[0] + 1);
    const auto addRow = [&](const std::array<std::int64_t, D> &first) {
      const std::size_t start = linear(first);
      const Index b = cellStart_[start], e = cellStart_[start + rowCells];
      if (b == e)
        return;
      if (count == CandidateRanges::capacity)
        throw std::length_error("wash: a search radius spans too many cells");
      out.begin[count] = b;
      out.end[count] = e;
      ++count;
      total += e - b;
    };
    if (from[0] <= to[0]) {
      if constexpr (D == 2) {
        for (std::int64_t y = from[1]; y <= to[1]; ++y)
          addRow({from[0], y});
      } else {
        for (std::int64_t z = from[2]; z <= to[2]; ++z)
          for (std::int64_t y = from[1]; y <= to[1]; ++y)
            addRow({from[0], y, z});
      }
    }
    out.count = count;
    out.total = total;
  }

  double radius() const { return radius_; }

  /// For each row p, the largest of radius[q] over the rows q in the cells
  /// within reach of p's cell: a search radius for p that every q with
  /// |x_q - x_p| <= radius[q] <= reach lies within. A max-filter of the cells'
  /// largest radii over a box of half-width reach / cell size (plus two cells,
  /// for the rounding of cell coordinates), one axis at a time, so a particle
  /// far from any large radius searches with a small one. `radius` may be
  /// out's data.
  void nearbyLargest(const double *radius, double reach, std::vector<double> &out) const {
    const std::size_t cells = cellStart_.size() - 1;
    std::vector<double> largest(cells, 0.0), swept(cells);
    WASH_OMP(parallel for if(cells >= parallelMinimum) schedule(static))
    for (std::size_t c = 0; c < cells; ++c)
      for (Index q = cellStart_[c]; q < cellStart_[c + 1]; ++q)
        largest[c] = std::max(largest[c], radius[q]);
    const double span = std::floor(reach * inverse_);
    const std::int64_t half = (span < 1e6 ? std::int64_t(span) : std::int64_t(1e6)) + 2;
    std::size_t stride = 1;
    for (int a = 0; a < D; ++a) {
      const std::int64_t n = dims_[a];
      WASH_OMP(parallel for if(cells >= parallelMinimum) schedule(static))
      for (std::size_t c = 0; c < cells; ++c) {
        const std::int64_t at = std::int64_t(c / stride) % n;
        const std::int64_t from = std::max<std::int64_t>(0, at - half),
                           to = std::min<std::int64_t>(n - 1, at + half);
        const std::size_t base = c - std::size_t(at) * stride;
        double m = 0.0;
        for (std::int64_t k = from; k <= to; ++k)
          m = std::max(m, largest[base + std::size_t(k) * stride]);
        swept[c] = m;
      }
      largest.swap(swept);
      stride *= std::size_t(n);
    }
    out.resize(cellStart_.empty() ? 0 : cellStart_[cells]);
    WASH_OMP(parallel for if(cells >= parallelMinimum) schedule(static))
    for (std::size_t c = 0; c < cells; ++c)
      for (Index q = cellStart_[c]; q < cellStart_[c + 1]; ++q)
        out[q] = largest[c];
  }

  /// The cells of x - r and x + r when r is the cell size and x lies well
  /// inside its cell: the one before and the one after x's, found with one
  /// multiplication. The products and quotients involved are within 3e-16
  /// relative of their exact values, so the cells are those of the exact
  /// arithmetic unless x / r lies within a hair of an integer; false then,
  /// and the caller computes both as coordinate() does.
  bool neighbourCells(double x, double r, std::int64_t &first, std::int64_t &last) const {
    std::int64_t whole;
    if (r != radius_ || !clearOfIntegers(x * inverse_, 2.0, whole))
      return false;
    first = whole - 1;
    last = whole + 1;
    return true;
  }

  /// floor(x / radius_), the division rounded as written, then floored (the
  /// canonical cell, detail::cellCoordinate), mostly without dividing: x * (1 / radius_) is within
  /// 4e-16 relative of that quotient, so the floors agree unless the product
  /// lies within a hair of an integer, and then the division decides. (A
  /// division is the slowest step of setting up a scan.)
  std::int64_t coordinate(double x) const {
    std::int64_t whole;
    if (clearOfIntegers(x * inverse_, 1.0, whole)) [[likely]]
      return whole;
    return detail::cellCoordinate(x, radius_);
  }

private:
  static std::string tooManyCells(double span, double r) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "wash: the particles span %.3g cells %.17g wide (from the lowest particle to "
                  "the highest on each axis), more than the %.0f a backend's cell grid can index "
                  "(docs/backends.md, \"Limits\"): use a larger influence radius or smoothing "
                  "length, or keep the particles closer together (is one far outside the "
                  "others?)",
                  span, r, double(std::numeric_limits<Index>::max()));
    return text;
  }

  /// floor(q) into `whole`, and whether q lies farther than
  /// 1e-12 * (|q| + slack) from every integer; false for a NaN, infinite or
  /// huge q.
  static bool clearOfIntegers(double q, double slack, std::int64_t &whole) {
    if (!(std::fabs(q) < 0x1p62))
      return false;
    whole = static_cast<std::int64_t>(q); // truncated, then floored
    whole -= q < static_cast<double>(whole);
    const double above = q - static_cast<double>(whole);
    const double hair = 1e-12 * (std::fabs(q) + slack);
    return above > hair && above < 1.0 - hair;
  }

  std::size_t linear(const std::array<std::int64_t, D> &c) const {
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a)
      index = index * std::size_t(dims_[a]) + std::size_t(c[a] - lo_[a]);
    return index;
  }
  double radius_ = 1.0, inverse_ = 1.0;
  std::array<std::int64_t, D> lo_{}, dims_{};
  std::vector<Index> cellStart_, cell_, next_;
};

} // namespace wash::backend
