//===- wash/mpi/domain.hpp - which rank owns which particles ------*- C++ -*-===//
//
// Space is cut along a Z-order (Morton) curve over the cells of the canonical
// grid (cell size = influence radius): each rank owns a contiguous range of
// cell keys, so a cell and all its particles belong to one rank. The ranges
// start with about equal particle counts (from a sample of every rank's); later
// they are recomputed to balance the
// work measured on each rank, when its imbalance grows past a threshold.
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
#include <stdexcept>
#include <vector>

namespace wash::mpi {

template <int D> class Domain {
public:
  using Cell = std::array<std::int64_t, D>;
  static constexpr int bits = 21;
  static constexpr std::int64_t offset = std::int64_t(1) << (bits - 1);

  void setCellSize(double cellSize) { cellSize_ = cellSize; }
  double cellSize() const { return cellSize_; }

  Cell cellOf(const Vec<double, D> &p) const {
    Cell c;
    for (int a = 0; a < D; ++a)
      c[a] = wash::detail::cellCoordinate(p.at(a), cellSize_);
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
        throw std::out_of_range("wash mpi: a particle is more than 2^19 cells from where the particles started");
      key |= spread(std::uint64_t(u)) << a;
    }
    return key;
  }

  /// The key of the cell a position lies in.
  template <typename PosT> std::uint64_t keyAt(const PosT &p) const {
    return keyOf(cellOf(Vec<double, D>(p)));
  }

  int ownerOf(std::uint64_t key) const {
    return int(std::upper_bound(splitters_.begin(), splitters_.end(), key) - splitters_.begin());
  }

  /// Searches since the splitters were last set (redistribute counts them).
  int &searchesSinceBalance() { return searches_; }

  /// Splitters from a weighted sample of every rank's keys (collective), so
  /// that every rank gets about the same work. `work` is this rank's measured
  /// work (busySeconds); within a rank, a particle's share of it grows with the
  /// particles sharing its cell (its neighbours grow with them: water at a
  /// free surface costs less than water at depth).
  void balance(std::vector<std::uint64_t> localKeys, double work) {
    searches_ = 0;
    std::sort(localKeys.begin(), localKeys.end());
    // Every rank receives every rank's samples: 1024 each up to 64 ranks,
    // then fewer (64 at least), 64 Ki samples (1 MiB) in all.
    const std::size_t perRank = std::clamp<std::size_t>(65536 / std::size_t(ranks()), 64, 1024);
    const std::size_t n = localKeys.size(), samples = std::min<std::size_t>(n, perRank);
    // ahead[k]: the cell-share weight of the particles before k in key order.
    std::vector<double> ahead(n);
    double sum = 0.0;
    for (std::size_t k = 0; k < n;) {
      std::size_t end = k;
      while (end < n && localKeys[end] == localKeys[k])
        ++end;
      const double share = double(end - k);
      for (std::size_t j = k; j < end; ++j, sum += share)
        ahead[j] = sum;
      k = end;
    }
    std::vector<std::uint64_t> sample;
    std::vector<double> weight;
    for (std::size_t s = 0; s < samples; ++s) {
      const double target = sum * double(s) / double(samples);
      const std::size_t k =
          std::size_t(std::upper_bound(ahead.begin(), ahead.end(), target) - ahead.begin()) - 1;
      sample.push_back(localKeys[k]);
      weight.push_back(work / double(samples));
    }
    std::vector<std::uint64_t> keys = allgatherv(sample);
    std::vector<double> weights = allgatherv(weight);
    std::vector<std::size_t> order(keys.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return keys[a] != keys[b] ? keys[a] < keys[b] : a < b;
    });
    double total = 0;
    for (double w : weights)
      total += w;
    splitters_.assign(ranks() - 1, ~std::uint64_t(0));
    double before = 0;
    int next = 1;
    for (std::size_t k : order) {
      while (next < ranks() && before >= total * next / ranks())
        splitters_[next++ - 1] = keys[k];
      before += weights[k];
    }
  }

private:
  static Cell filled(std::int64_t v) {
    Cell c;
    c.fill(v);
    return c;
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
  std::vector<std::uint64_t> splitters_; ///< rank r owns [splitters[r-1], splitters[r])
};

} // namespace wash::mpi
