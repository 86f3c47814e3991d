//===- wash/mpi/domain.hpp - which rank owns which particles ------*- C++ -*-===//
//
// Space is cut by recursive bisection over the cells of the canonical grid
// (cell size = influence radius): the ranks are halved, and so is their piece
// of space, across its longest side, until each rank has a box of cells, so a
// cell and all its particles belong to one rank, and pieces stay about as
// wide as they are long (the halo, and so the bytes a rank sends, grows with
// a piece's surface). The cuts start with about equal particle counts (from a
// sample of every rank's); later they are recomputed to balance the work
// measured on each rank, when its imbalance grows past a threshold. Cell keys
// along a Z-order (Morton) curve order the sample and name cells.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/search_geometry.hpp>
#include <wash/detail/cell.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace wash::mpi {

/// Calls visit(cell) for every cell of the box [first, last], x fastest, while
/// it returns true.
template <typename Cell, typename Visit>
void forEachCellIn(const Cell &first, const Cell &last, Visit visit) {
  Cell c = first;
  while (visit(c)) {
    std::size_t a = 0;
    while (a < c.size() && c[a] == last[a])
      c[a] = first[a], ++a;
    if (a == c.size())
      return;
    ++c[a];
  }
}

template <int D> class Domain {
public:
  using Cell = std::array<std::int64_t, D>;
  static constexpr int bits = 21;
  static constexpr std::int64_t offset = std::int64_t(1) << (bits - 1);

  void setCellSize(double cellSize) { cellSize_ = cellSize; }
  double cellSize() const { return cellSize_; }

  /// Clamped to +-2^62 (a non-finite coordinate to 0): a position no cell
  /// holds still gets one, and the finite checks or keyOf name the problem.
  Cell cellOf(const Vec<double, D> &p) const {
    Cell c;
    for (int a = 0; a < D; ++a) {
      const double q = p.at(a) / cellSize_;
      c[a] = std::abs(q) < 0x1p62 ? wash::detail::cellCoordinate(p.at(a), cellSize_)
             : q > 0.0            ? std::int64_t(1) << 62
             : q < 0.0            ? -(std::int64_t(1) << 62)
                                  : 0;
    }
    return c;
  }

  /// Keys count cells from `lowest` (the lowest cell of any particle at the
  /// start) placed at 2^19: the particles' box then starts on a power of two
  /// of the curve, so its first cuts are quadrants (octants) of that box, not
  /// of all space around the origin, which a box across 0 would split into
  /// scattered pieces. Particles may later move 2^19 cells below it.
  void setLowestCell(const Cell &lowest) {
    for (int a = 0; a < D; ++a)
      origin_[a] = lowest[a] - offset / 2;
  }

  /// Z-order key of a cell: the bits of the coordinates counted from the
  /// origin interleaved, x in the lowest bit.
  std::uint64_t keyOf(const Cell &c) const {
    std::uint64_t key = 0;
    for (int a = 0; a < D; ++a) {
      std::int64_t u = c[a] - origin_[a];
      if (u < 0 || u >= (std::int64_t(1) << bits))
        throw std::out_of_range(tooFar(c, a));
      key |= spread(std::uint64_t(u)) << a;
    }
    return key;
  }

  /// The rank that owns a cell: the leaf of the bisection tree it falls in.
  int ownerOf(const Cell &c) const {
    int node = nodes_.empty() ? -1 : 0;
    while (node >= 0) {
      const Cut &cut = nodes_[std::size_t(node)];
      node = c[std::size_t(cut.axis)] < cut.at ? cut.below : cut.above;
    }
    return -node - 1;
  }

  /// The rank that owns the cell a position lies in.
  template <typename PosT> int ownerAt(const PosT &p) const {
    return ownerOf(cellOf(Vec<double, D>(p)));
  }

  /// Searches since the domain was last balanced (redistribute counts them).
  int &searchesSinceBalance() { return searches_; }

  /// A new bisection from a weighted sample of every rank's cells (collective),
  /// so that every rank gets about the same work. `work` is this rank's
  /// measured work (busySeconds); within a rank, a particle's share of it
  /// grows with the particles sharing its cell (its neighbours grow with them:
  /// water at a free surface costs less than water at depth).
  void balance(const std::vector<Cell> &localCells, double work) {
    searches_ = 0;
    // Sampled along the Z-order curve, so that the sample covers space evenly.
    std::vector<std::pair<std::uint64_t, std::size_t>> byKey(localCells.size());
    for (std::size_t k = 0; k < localCells.size(); ++k)
      byKey[k] = {keyOf(localCells[k]), k};
    std::sort(byKey.begin(), byKey.end());
    // Every rank receives every rank's samples: 1024 each up to 64 ranks,
    // then fewer (64 at least), 64 Ki samples in all.
    const std::size_t perRank = std::clamp<std::size_t>(65536 / std::size_t(ranks()), 64, 1024);
    const std::size_t n = byKey.size(), samples = std::min<std::size_t>(n, perRank);
    // ahead[k]: the cell-share weight of the particles before k in key order.
    std::vector<double> ahead(n);
    double sum = 0.0;
    for (std::size_t k = 0; k < n;) {
      std::size_t end = k;
      while (end < n && byKey[end].first == byKey[k].first)
        ++end;
      const double share = double(end - k);
      for (std::size_t j = k; j < end; ++j, sum += share)
        ahead[j] = sum;
      k = end;
    }
    std::vector<std::uint64_t> sample; // D coordinates a sample
    std::vector<double> weight;
    for (std::size_t s = 0; s < samples; ++s) {
      const double target = sum * double(s) / double(samples);
      const std::size_t k =
          std::size_t(std::upper_bound(ahead.begin(), ahead.end(), target) - ahead.begin()) - 1;
      for (int a = 0; a < D; ++a)
        sample.push_back(std::uint64_t(localCells[byKey[k].second][std::size_t(a)]));
      weight.push_back(work / double(samples));
    }
    const std::vector<std::uint64_t> coordinates = allgatherv(sample);
    Samples all;
    all.weight = allgatherv(weight);
    all.cell.resize(all.weight.size());
    for (std::size_t k = 0; k < all.cell.size(); ++k)
      for (int a = 0; a < D; ++a)
        all.cell[k][std::size_t(a)] = std::int64_t(coordinates[k * D + std::size_t(a)]);
    std::vector<std::size_t> every(all.cell.size());
    for (std::size_t k = 0; k < every.size(); ++k)
      every[k] = k;
    nodes_.clear();
    bisect(all, every, 0, ranks());
  }

private:
  /// Cells with coordinate < at on `axis` lie below the cut; a child >= 0 is
  /// a node, a negative child -r - 1 is rank r.
  struct Cut {
    int axis = 0;
    std::int64_t at = 0;
    int below = -1, above = -1;
  };
  struct Samples {
    std::vector<Cell> cell;
    std::vector<double> weight;
  };

  static Cell filled(std::int64_t v) {
    Cell c;
    c.fill(v);
    return c;
  }

  /// Recursive bisection: ranks [first, last) share the samples `at`; the
  /// first half of the ranks gets the cells below a cut across the longest
  /// side of the samples' box, placed where the weight below comes closest to
  /// their share. Every rank computes the same tree from the same samples.
  /// Returns the child to store: a node, or -rank - 1.
  int bisect(const Samples &all, std::vector<std::size_t> at, int first, int last) {
    if (last - first == 1)
      return -first - 1;
    const int lower = (last - first) / 2;
    int axis = 0;
    std::int64_t longest = -1;
    for (int a = 0; a < D && !at.empty(); ++a) {
      std::int64_t lo = all.cell[at[0]][std::size_t(a)], hi = lo;
      for (std::size_t k : at) {
        lo = std::min(lo, all.cell[k][std::size_t(a)]);
        hi = std::max(hi, all.cell[k][std::size_t(a)]);
      }
      if (hi - lo > longest)
        longest = hi - lo, axis = a;
    }
    const std::size_t A = std::size_t(axis);
    std::sort(at.begin(), at.end(), [&](std::size_t x, std::size_t y) {
      return all.cell[x][A] != all.cell[y][A] ? all.cell[x][A] < all.cell[y][A] : x < y;
    });
    double total = 0.0;
    for (std::size_t k : at)
      total += all.weight[k];
    const double target = total * double(lower) / double(last - first);
    // Candidate cuts: each sample's coordinate (the weight strictly below it)
    // and one past the last.
    std::int64_t cut = at.empty() ? 0 : all.cell[at.back()][A] + 1;
    double best = at.empty() ? 0.0 : std::abs(total - target), below = 0.0;
    std::size_t split = at.size();
    for (std::size_t k = 0; k < at.size(); ++k) {
      if (k == 0 || all.cell[at[k]][A] != all.cell[at[k - 1]][A]) {
        if (std::abs(below - target) < best)
          best = std::abs(below - target), cut = all.cell[at[k]][A], split = k;
      }
      below += all.weight[at[k]];
    }
    const int node = int(nodes_.size());
    nodes_.push_back({axis, cut, 0, 0});
    std::vector<std::size_t> above(at.begin() + std::ptrdiff_t(split), at.end());
    at.resize(split);
    const int belowChild = bisect(all, std::move(at), first, first + lower);
    const int aboveChild = bisect(all, std::move(above), first + lower, last);
    nodes_[std::size_t(node)].below = belowChild;
    nodes_[std::size_t(node)].above = aboveChild;
    return node;
  }

  /// What keyOf says of a cell outside the curve, and what to change.
  std::string tooFar(const Cell &c, int a) const {
    const std::int64_t lowest = origin_[a] + offset / 2;
    char text[512];
    std::snprintf(
        text, sizeof text,
        "wash mpi: a particle is in cell %lld of axis %d (cells %.17g wide, it "
        "starts at %.17g), %lld cells from cell %lld, the lowest any particle started in: "
        "the MPI backend indexes 2^21 cells per axis, from 2^19 below that one to 3 x "
        "2^19 above it (docs/backends.md, \"Limits\"); keep the particles within 2^19 cells "
        "of one another (or inside a periodic box), or use a larger influence radius "
        "or smoothing length",
        static_cast<long long>(c[std::size_t(a)]), a, cellSize_,
        double(c[std::size_t(a)]) * cellSize_, static_cast<long long>(c[std::size_t(a)] - lowest),
        static_cast<long long>(lowest));
    return text;
  }

  /// The 21 low bits of v, moved to every D-th bit.
  static std::uint64_t spread(std::uint64_t v) {
    if constexpr (D == 2) {
      v &= 0x1fffff;
      v = (v | (v << 16)) & 0x0000ffff0000ffffull;
      v = (v | (v << 8)) & 0x00ff00ff00ff00ffull;
      v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0full;
      v = (v | (v << 2)) & 0x3333333333333333ull;
      v = (v | (v << 1)) & 0x5555555555555555ull;
    } else {
      v &= 0x1fffff;
      v = (v | (v << 32)) & 0x001f00000000ffffull;
      v = (v | (v << 16)) & 0x001f0000ff0000ffull;
      v = (v | (v << 8)) & 0x100f00f00f00f00full;
      v = (v | (v << 4)) & 0x10c30c30c30c30c3ull;
      v = (v | (v << 2)) & 0x1249249249249249ull;
    }
    return v;
  }

  double cellSize_ = 1.0;
  Cell origin_ = filled(-offset); ///< the cell of key coordinate 0
  int searches_ = 0;
  std::vector<Cut> nodes_; ///< the bisection tree, its root first; none: rank 0 owns all
};

} // namespace wash::mpi
