// A list built with Distances keeps, for each neighbour, bit for bit the
// distance the user's `(n.get_pos() - p.get_pos()).magnitude()` computes (the
// translator reads it in place of that expression), on every scan path, with
// the same neighbours in the same order as a list without distances.
#include "scan_paths.hpp"

#include <wash/backend/neighbours.hpp>

#include <gtest/gtest.h>

#include <cstring>
#include <random>

using namespace wash::backend;

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <int D> void compareDistances(unsigned seed, int n, double extent, double r) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-extent, extent);
  Column<wash::Vec<double, D>> pos;
  Column<std::uint64_t> id;
  for (int k = 0; k < n; ++k) {
    wash::Vec<double, D> v;
    for (int a = 0; a < D; ++a)
      *v[a] = k % 5 ? u(rng) : 0.125 * std::round(8 * u(rng)); // some ties at the radius
    pos.push_back(v);
    id.push_back(std::uint64_t(k));
  }
  CellGrid<D> grid;
  std::vector<Index> order;
  grid.sort(pos, id, r, order);
  permute(pos, order);
  std::size_t pairs = 0;
  for (Index i = 0; i < pos.size(); ++i) {
    std::vector<std::size_t> plain;
    for (const NeighbourRef &m : Neighbours<D, wash::Vec<double, D>>(grid, pos, i))
      plain.push_back(m.index);
    const Neighbours<D, wash::Vec<double, D>, NeighbourRef, true> list(grid, pos, i);
    ASSERT_EQ(list.size(), plain.size()) << "particle " << i;
    for (std::size_t k = 0; k < list.size(); ++k) {
      const NeighbourRef &m = list[k];
      ASSERT_EQ(m.index, plain[k]);
      const double expected = (pos[m] - pos[i]).magnitude();
      ASSERT_TRUE(sameBits(list.distance(m), expected))
          << "particle " << i << ", neighbour " << m.index << ": " << list.distance(m)
          << " against " << expected;
      ASSERT_TRUE(sameBits(list.distance(m), (pos[i] - pos[m]).magnitude()));
      ++pairs;
    }
  }
  EXPECT_GT(pairs, std::size_t(10 * n));
}

} // namespace

TEST(NeighbourDistances, EqualTheUsersMagnitudeIn2D) {
  onEveryScanPath([] { compareDistances<2>(1, 1500, 3.0, 0.35); });
}

TEST(NeighbourDistances, EqualTheUsersMagnitudeIn3D) {
  onEveryScanPath([] { compareDistances<3>(2, 1500, 1.0, 0.25); });
}
