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
#include <wash/backend/periodic.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/mpi/domain.hpp>
#include <wash/detail/box.hpp>
#include <wash/detail/cell.hpp>
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

/// Collective: sends the largest search radius of each of this rank's cells
/// that another rank's particles may pair with (`interior(cell)` false, or
/// near a periodic face) to the ranks owning cells within `reach` cells of it
/// (`ownerOf`), or of its image across the faces it is near: those ranks'
/// images lie there. Returns what the other ranks sent here.
template <int D, typename Particles, typename SmoothingLength, typename OwnerOf,
          typename Interior>
CellReach<D> exchangeBoundaryReach(const Particles &P, const std::vector<backend::Index> &owned,
                                   const Domain<D> &domain,
                                   const RowReach<SmoothingLength> &reachOf,
                                   const ::wash::detail::Box &box, std::int64_t reach,
                                   OwnerOf ownerOf, Interior interior) {
  using Cell = typename Domain<D>::Cell;
  const int me = rank();
  const double cellSize = domain.cellSize();
  auto faceShift = [&](const Cell &cell, int a) {
    const double margin = double(reach + 1) * cellSize;
    if (!box.periodic[a])
      return 0;
    if (double(cell[a] + 1) * cellSize - box.lo[a] <= margin)
      return 1;
    return box.hi[a] - double(cell[a]) * cellSize <= margin ? -1 : 0;
  };
  auto faceShifts = [&](const Cell &cell) {
    std::array<int, D> shift;
    for (int a = 0; a < D; ++a)
      shift[a] = faceShift(cell, a);
    return shift;
  };
  using Largest = typename CellReach<D>::Largest;
  std::unordered_map<std::uint64_t, Largest> mine;
  for (backend::Index i : owned) {
    const Cell cell = domain.cellOf(Vec<double, D>(P.pos[i]));
    if (interior(cell) && faceShifts(cell) == std::array<int, D>{})
      continue;
    Largest &largest = mine.try_emplace(domain.keyOf(cell), Largest{cell, 0.0}).first->second;
    largest.radius = std::max(largest.radius, reachOf.search(i));
  }
  CellReach<D> theirs;
  theirs.exchange(mine, [&](const Cell &cell, std::vector<int> &near) {
    auto walkAround = [&](const Cell &centre, std::int64_t width) {
      Cell first, last;
      for (int a = 0; a < D; ++a)
        first[a] = centre[a] - width, last[a] = centre[a] + width;
      forEachCellIn(first, last, [&](const Cell &x) {
        const int owner = ownerOf(x);
        if (owner != me && std::find(near.begin(), near.end(), owner) == near.end())
          near.push_back(owner);
        return true;
      });
    };
    walkAround(cell, reach);
    backend::forEachImageShift<D>(faceShifts(cell), [&](const std::array<int, D> &k) {
      Cell image = cell;
      for (int b = 0; b < D; ++b)
        if (k[b])
          image[b] = ::wash::detail::cellCoordinate(
              box.shifted((double(cell[b]) + 0.5) * cellSize, k[b], b), cellSize);
      walkAround(image, reach + 1); // + 1: the image of a cell straddles two
    });
  });
  return theirs;
}

} // namespace wash::mpi
