//===- wash/backend/search_geometry.hpp - sizes of one neighbour search -*- C++ -*-===//
//
// What a generated search needs to know before it sorts: how far the search
// reaches (the width of periodic images and MPI halos) and the cell size of
// the grid. Under the influence-radius rule both are the radius. Under the
// smoothing-length rule (detail/search.hpp) the reach is the largest support
// radius, and the cells are finer, so that particles with small support
// radii scan few candidates; the neighbour order (by id) does not depend on
// the cells. Under the symmetric rule the cells are the same, and the search
// of particle i reaches the largest radius near it (NeighbourTable).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/detail/search.hpp>

#include <algorithm>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace wash::backend {

struct SearchGeometry {
  double reach = 0.0;    ///< largest search radius
  double cellSize = 1.0; ///< side of the grid's cells
  double support = 0.0;  ///< smoothing-length rule: support radius in units of h
  bool symmetric = false; ///< pairs within the larger support radius

  /// The search radius of a particle with smoothing length h.
  double radiusOf(double h) const { return detail::supportRadius(support, h); }
  /// The cell size of a domain decomposition whose halos reach as far as any
  /// later search needs: this search's reach (1 if every radius is 0).
  double domainCellSize() const { return reach > 0.0 ? reach : 1.0; }
};

inline SearchGeometry fixedGeometry(double radius) { return {radius, radius, 0.0}; }

/// What a generated search passes for the smoothing lengths under the
/// influence-radius rule, which reads none (otherwise a callable h(row)).
struct NoSmoothingLength {};

/// The radii of row q under the search rule, given its smoothing length
/// (`h(q)`, when the rule reads one): what lets periodic images and MPI
/// halos reach only as far as each particle's pairs do.
template <typename SmoothingLength> struct RowReach {
  const SearchGeometry &at;
  SmoothingLength h;

  static constexpr bool fixed = std::is_same_v<SmoothingLength, NoSmoothingLength>;

  /// How far q's own search reaches.
  double search(Index q) const {
    if constexpr (fixed)
      return at.reach;
    else
      return at.radiusOf(double(h(q)));
  }
  /// How far another particle's search must reach to pair with q whatever
  /// its own radius: q's radius where a pair takes the larger one, else 0.
  double sender(Index q) const {
    if constexpr (fixed)
      return at.reach;
    else
      return at.symmetric ? at.radiusOf(double(h(q))) : 0.0;
  }
};

/// The geometry for the smoothing-length rule over the particles at `rows`.
/// `globalMax`, if given, combines a rank's largest radius with the other ranks'.
/// `symmetric`: wash::Support::Symmetric.
template <typename RealT>
SearchGeometry smoothingGeometry(double support, const Column<RealT> &h,
                                 const Column<std::uint64_t> &ids, const std::vector<Index> &rows,
                                 const detail::Box &box, int dims, std::uint64_t step,
                                 const char *kernel, double (*globalMax)(double) = nullptr,
                                 bool symmetric = false) {
  auto fail = [&](const std::string &what) {
    throw detail::RunError("step " + std::to_string(step) + ": kernel '" + kernel + "': " + what);
  };
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (Index p : rows) {
    if (std::string bad = detail::checkSmoothingLength(double(h[p])); !bad.empty())
      fail("particle " + std::to_string(ids[p]) + ": " + bad);
    const double r = detail::supportRadius(support, double(h[p]));
    largest = std::max(largest, r);
    smallest = std::min(smallest, r);
  }
  if (globalMax)
    largest = globalMax(largest);
  if (rows.empty())
    smallest = largest;
  if (std::string bad = detail::checkPeriodicSupport(box, dims, largest); !bad.empty())
    fail(bad);
  SearchGeometry g;
  g.reach = largest;
  g.support = support;
  g.symmetric = symmetric;
  // Half the smallest radius, but no finer than a quarter of the largest:
  // CandidateRanges holds the rows of a radius of up to four cells.
  g.cellSize = std::max(largest / 4.0, smallest / 2.0);
  if (!(g.cellSize > 0.0))
    g.cellSize = 1.0; // all radii 0: any cell size finds coincident particles
  return g;
}

} // namespace wash::backend
