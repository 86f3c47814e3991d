// The symmetric smoothing-length rule (wash::Support::Symmetric): j is a
// neighbour of i when |x_j - x_i|^2 <= (k max(h_i, h_j))^2, in ascending id
// order. A NeighbourTable built for it must list exactly those pairs, on
// every scan path, whatever cell size the backend picks.
#include <wash/backend/neighbour_table.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/detail/neighbour_search.hpp>

#include "scan_paths.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace wash::backend;

namespace {

using Lists = std::vector<std::vector<std::uint64_t>>;

template <int D> struct Cloud {
  Column<wash::Vec<double, D>> pos;
  Column<std::uint64_t> id;
  Column<double> h;
};

/// Every particle's neighbour ids (by id) from a NeighbourTable under `rule`.
template <int D> Lists tableLists(Cloud<D> c, double support, bool symmetric) {
  std::vector<Index> rows(c.pos.size());
  for (Index i = 0; i < rows.size(); ++i)
    rows[i] = i;
  const SearchGeometry g = smoothingGeometry(support, c.h, c.id, rows, wash::detail::Box{}, D, 1,
                                             "test", nullptr, symmetric);
  CellGrid<D> grid;
  std::vector<Index> order;
  grid.sort(c.pos, c.id, g.cellSize, order);
  permute(c.pos, order);
  permute(c.id, order);
  permute(c.h, order);
  NeighbourTable<D, wash::Vec<double, D>> table;
  table.build(grid, c.pos, c.id, c.h, g, rows);
  Lists out(c.pos.size());
  for (Index i = 0; i < c.pos.size(); ++i)
    for (const StoredNeighbourRef &n : table.list(i))
      out[c.id[i]].push_back(c.id[n]);
  return out;
}

/// The rule itself, over every pair, in the reference's arithmetic.
template <int D> Lists bruteForce(const Cloud<D> &c, double support) {
  Lists out(c.pos.size());
  for (std::size_t i = 0; i < c.pos.size(); ++i) {
    std::vector<std::uint64_t> ids;
    for (std::size_t j = 0; j < c.pos.size(); ++j) {
      const double pair = wash::detail::pairRadius(wash::detail::supportRadius(support, c.h[i]),
                                                   wash::detail::supportRadius(support, c.h[j]));
      if (j != i && wash::detail::withinRadius<D>(c.pos[i], c.pos[j], pair))
        ids.push_back(c.id[j]);
    }
    std::sort(ids.begin(), ids.end());
    out[c.id[i]] = ids;
  }
  return out;
}

/// n particles in [-extent, extent]^D, h from hMin to hMax, large near the
/// origin, small far from it, so that most pairs have unequal radii.
template <int D> Cloud<D> cloud(unsigned seed, int n, double extent, double hMin, double hMax) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-extent, extent), jitter(0.9, 1.1);
  Cloud<D> c;
  for (int k = 0; k < n; ++k) {
    wash::Vec<double, D> v;
    double r2 = 0.0;
    for (int a = 0; a < D; ++a) {
      *v[a] = u(rng);
      r2 += v.at(a) * v.at(a);
    }
    c.pos.push_back(v);
    c.id.push_back(std::uint64_t((k * 7919) % n)); // storage order is not id order
    const double near = std::exp(-r2 / (extent * extent * 0.1));
    c.h.push_back(std::min(hMax, (hMin + (hMax - hMin) * near) * jitter(rng)));
  }
  return c;
}

std::size_t pairs(const Lists &lists) {
  std::size_t n = 0;
  for (const auto &l : lists)
    n += l.size();
  return n;
}

} // namespace

// i (h = 0.1) sees j 1.5 away only through j's support 2 h_j = 2; a third
// particle with a small h, 3 away from both, is nobody's neighbour.
TEST(SymmetricSupport, APairFoundOnlyThroughTheNeighboursSmoothingLength) {
  Cloud<2> c;
  c.pos = {wash::Vec<double, 2>(0.0, 0.0), wash::Vec<double, 2>(1.5, 0.0),
           wash::Vec<double, 2>(0.0, 3.0)};
  c.id = {0, 1, 2};
  c.h = {0.1, 1.0, 0.1};
  onEveryScanPath([&] {
    EXPECT_EQ(tableLists(c, 2.0, true), (Lists{{1}, {0}, {}}));
    EXPECT_EQ(tableLists(c, 2.0, false), (Lists{{}, {0}, {}})); // gather: only j lists i
  });
}

// On the pair radius itself (the test is <=, in the same double arithmetic).
TEST(SymmetricSupport, APairExactlyAtThePairRadius) {
  Cloud<3> c;
  c.pos = {wash::Vec<double, 3>(0.0, 0.0, 0.0), wash::Vec<double, 3>(0.0, 0.0, 1.0),
           wash::Vec<double, 3>(0.0, 1.0, 0.0)};
  c.id = {2, 0, 1}; // (ids index the lists)
  c.h = {0.25, 0.5, 0.4999999999999999};
  onEveryScanPath([&] {
    const Lists lists = tableLists(c, 2.0, true);
    EXPECT_EQ(lists, bruteForce(c, 2.0));
    EXPECT_EQ(lists[2], (std::vector<std::uint64_t>{0})); // 1 <= 2 * 0.5; 1 > 2 * 0.49999..
  });
}

TEST(SymmetricSupport, MatchesTheRuleIn2D) {
  onEveryScanPath([] {
    const Cloud<2> c = cloud<2>(7, 1500, 2.0, 0.03, 0.3);
    const Lists lists = tableLists(c, 2.0, true);
    EXPECT_EQ(lists, bruteForce(c, 2.0));
    EXPECT_GT(pairs(lists), pairs(tableLists(c, 2.0, false))); // the rule matters here
  });
}

TEST(SymmetricSupport, MatchesTheRuleIn3D) {
  onEveryScanPath([] {
    const Cloud<3> c = cloud<3>(8, 2000, 1.0, 0.03, 0.25);
    const Lists lists = tableLists(c, 2.0, true);
    EXPECT_EQ(lists, bruteForce(c, 2.0));
    EXPECT_GT(pairs(lists), pairs(tableLists(c, 2.0, false)));
    // i lists j exactly when j lists i.
    for (std::uint64_t i = 0; i < lists.size(); ++i)
      for (std::uint64_t j : lists[i])
        EXPECT_TRUE(std::binary_search(lists[j].begin(), lists[j].end(), i)) << i << " " << j;
  });
}
