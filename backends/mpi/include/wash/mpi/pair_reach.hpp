//===- wash/mpi/pair_reach.hpp - how far each particle's pairs reach -*- C++ -*-===//
//
// A halo copy is needed only where it can be some particle's neighbour. Under
// the influence-radius rule every pair reaches the radius; under the
// smoothing-length rules a pair (i, j) reaches i's support radius (searching
// i) or the larger of the two (symmetric rule), and supports vary: Sedov's
// blast grows them fourfold. Copying everything within the largest radius
// makes every halo as deep as the blast's. Instead each rank tells the ranks
// near its boundary cells the largest search radius of the particles in each
// (CellReach), and a particle goes to the owner of a cell only if it lies
// within max(its own pair radius, that cell's) of the cell's box.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace wash::mpi {

using backend::RowReach;

/// Whether p lies within `radius` of the box of `cell` (cells of side
/// `cellSize` anchored at 0), erring on the side of yes by far more than the
/// rounding of the canonical cell and of the search's distance test.
template <int D, typename Cell>
bool withinOfCell(const Vec<double, D> &p, const Cell &cell, double cellSize, double radius) {
  double gap2 = 0.0;
  for (int a = 0; a < D; ++a) {
    const double lo = double(cell[a]) * cellSize, hi = lo + cellSize;
    const double slack = 1e-9 * (std::abs(lo) + cellSize);
    const double gap = std::max({0.0, lo - slack - p.at(a), p.at(a) - hi - slack});
    gap2 += gap * gap;
  }
  const double r = radius * (1.0 + 1e-9);
  return gap2 <= r * r;
}

/// The largest search radius in each cell of other ranks near this one: each
/// rank sends (cell key, radius) for each of its cells that has another
/// rank's cell within reach, to those ranks.
template <int D> class CellReach {
public:
  using Cell = std::array<std::int64_t, D>;
  struct Largest {
    Cell cell;
    double radius = 0.0;
  };

  /// Collective. `mine`: cell key -> the cell and the largest search radius
  /// of this rank's particles in it, for its cells near another rank;
  /// `nearRanks(cell, out)` appends the other ranks owning cells within
  /// reach of the cell.
  template <typename NearRanks>
  void exchange(const std::unordered_map<std::uint64_t, Largest> &mine, NearRanks nearRanks) {
    const int n = ranks();
    std::vector<std::vector<char>> out(n);
    std::vector<int> near;
    for (const auto &[key, largest] : mine) {
      near.clear();
      nearRanks(largest.cell, near);
      for (int r : near)
        append(out[r], key, largest.radius);
    }
    std::vector<std::size_t> counts(n);
    for (int r = 0; r < n; ++r)
      counts[r] = out[r].size();
    const std::vector<std::size_t> incoming = alltoallCounts(counts);
    const std::vector<char> in = alltoallv(out, incoming, traffic().halo);
    largest_.clear();
    for (std::size_t at = 0; at + entryBytes <= in.size(); at += entryBytes) {
      std::uint64_t key;
      double radius;
      std::memcpy(&key, in.data() + at, sizeof key);
      std::memcpy(&radius, in.data() + at + sizeof key, sizeof radius);
      largest_[key] = radius;
    }
  }

  /// The largest search radius among another rank's particles in the cell
  /// `key`, or a negative number if no rank near this one has particles there.
  double largestAt(std::uint64_t key) const {
    auto it = largest_.find(key);
    return it == largest_.end() ? -1.0 : it->second;
  }

private:
  static constexpr std::size_t entryBytes = sizeof(std::uint64_t) + sizeof(double);

  static void append(std::vector<char> &out, std::uint64_t key, double radius) {
    const std::size_t at = out.size();
    out.resize(at + entryBytes);
    std::memcpy(out.data() + at, &key, sizeof key);
    std::memcpy(out.data() + at + sizeof key, &radius, sizeof radius);
  }

  std::unordered_map<std::uint64_t, double> largest_;
};

} // namespace wash::mpi
