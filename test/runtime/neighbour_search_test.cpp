#include <wash/detail/neighbour_search.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>

using wash::detail::CellList;
using wash::detail::withinRadius;

namespace {

/// The definition, by brute force: every other particle within the radius,
/// sorted by (cell key, id).
template <int D>
std::vector<std::size_t> bruteForce(const CellList<D> &cells,
                                    const std::vector<wash::Vec<double, D>> &pos,
                                    const std::vector<std::uint64_t> &ids, std::size_t i,
                                    double radius) {
  std::vector<std::size_t> out;
  for (std::size_t j = 0; j < pos.size(); ++j)
    if (j != i && withinRadius<D>(pos[i], pos[j], radius))
      out.push_back(j);
  std::sort(out.begin(), out.end(), [&](std::size_t a, std::size_t b) {
    return std::make_tuple(cells.keyOf(pos[a]), ids[a]) < std::make_tuple(cells.keyOf(pos[b]), ids[b]);
  });
  return out;
}

template <int D>
void expectMatchesBruteForce(const std::vector<wash::Vec<double, D>> &pos,
                             const std::vector<std::uint64_t> &ids, double radius) {
  CellList<D> cells;
  cells.build(pos, ids, radius);
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    cells.neighbours(i, found);
    EXPECT_EQ(found, bruteForce<D>(cells, pos, ids, i, radius)) << "particle " << i;
  }
}

} // namespace

TEST(NeighbourSearch, RandomCloud2DMatchesBruteForce) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  std::vector<wash::Vec2D> pos;
  std::vector<std::uint64_t> ids;
  for (int k = 0; k < 600; ++k) {
    pos.push_back({u(rng), u(rng)});
    ids.push_back(599 - k); // storage order differs from id order
  }
  expectMatchesBruteForce<2>(pos, ids, 0.35);
}

TEST(NeighbourSearch, RandomCloud3DMatchesBruteForce) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<wash::Vec3D> pos;
  std::vector<std::uint64_t> ids;
  for (int k = 0; k < 500; ++k) {
    pos.push_back({u(rng), u(rng), u(rng)});
    ids.push_back((k * 7919) % 500);
  }
  expectMatchesBruteForce<3>(pos, ids, 0.3);
}

TEST(NeighbourSearch, ParticlesExactlyOnCellBordersAndAtTheRadius) {
  // A lattice with spacing equal to the cell size: every particle sits on a
  // cell corner and its axis neighbours lie exactly at the radius.
  const double radius = 0.5;
  std::vector<wash::Vec2D> pos;
  std::vector<std::uint64_t> ids;
  for (int y = -4; y <= 4; ++y)
    for (int x = -4; x <= 4; ++x) {
      pos.push_back({x * radius, y * radius});
      ids.push_back(ids.size());
    }
  expectMatchesBruteForce<2>(pos, ids, radius);
  CellList<2> cells;
  cells.build(pos, ids, radius);
  std::vector<std::size_t> found;
  cells.neighbours(40, found); // the origin: four axis neighbours at distance exactly r
  ASSERT_EQ(found.size(), 4u);
  // Canonical order: cells by (y, x), so below, left, right, above.
  EXPECT_EQ(pos[found[0]], wash::Vec2D(0.0, -0.5));
  EXPECT_EQ(pos[found[1]], wash::Vec2D(-0.5, 0.0));
  EXPECT_EQ(pos[found[2]], wash::Vec2D(0.5, 0.0));
  EXPECT_EQ(pos[found[3]], wash::Vec2D(0.0, 0.5));
}

TEST(NeighbourSearch, CoincidentParticlesAreNeighboursOrderedById) {
  std::vector<wash::Vec2D> pos(4, wash::Vec2D{1.0, 1.0});
  std::vector<std::uint64_t> ids{3, 1, 2, 0};
  CellList<2> cells;
  cells.build(pos, ids, 0.1);
  std::vector<std::size_t> found;
  cells.neighbours(0, found);
  EXPECT_EQ(found, (std::vector<std::size_t>{3, 1, 2})); // ids 0, 1, 2
}

TEST(NeighbourSearch, OrderDoesNotDependOnStorageOrder) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<wash::Vec2D> pos;
  std::vector<std::uint64_t> ids;
  for (int k = 0; k < 200; ++k) {
    pos.push_back({u(rng), u(rng)});
    ids.push_back(k);
  }
  std::vector<std::size_t> perm(pos.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<wash::Vec2D> pos2;
  std::vector<std::uint64_t> ids2;
  for (std::size_t k : perm) {
    pos2.push_back(pos[k]);
    ids2.push_back(ids[k]);
  }
  CellList<2> a, b;
  a.build(pos, ids, 0.25);
  b.build(pos2, ids2, 0.25);
  std::vector<std::size_t> fa, fb;
  for (std::size_t k = 0; k < perm.size(); ++k) {
    a.neighbours(perm[k], fa);
    b.neighbours(k, fb);
    ASSERT_EQ(fa.size(), fb.size());
    for (std::size_t n = 0; n < fa.size(); ++n)
      EXPECT_EQ(ids[fa[n]], ids2[fb[n]]);
  }
}

TEST(NeighbourSearch, PeriodicBoxMatchesMinimumImageBruteForce) {
  // Periodic in x and y (3D, z closed): every pair within the radius at its
  // minimum-image distance, seen at that image, ordered by (cell of image, id).
  wash::detail::Box box;
  box.defined = true;
  box.lo = {-1.0, 0.0, 0.0};
  box.hi = {1.0, 1.5, 1.0};
  box.periodic = {true, true, false};
  const double r = 0.3;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(-1.0, 1.0), uy(0.0, 1.5), uz(0.0, 1.0);
  std::vector<wash::Vec3D> pos;
  std::vector<std::uint64_t> ids;
  for (int k = 0; k < 400; ++k) {
    pos.push_back({ux(rng), uy(rng), uz(rng)});
    ids.push_back(399 - k);
  }
  CellList<3> cells;
  cells.build(pos, ids, r);
  std::vector<std::size_t> found;
  std::vector<wash::Vec3D> images;
  for (std::size_t i = 0; i < pos.size(); ++i) {
    cells.periodicNeighbours(i, box, found, images, [](double v) { return v; });
    std::vector<std::tuple<CellList<3>::Key, std::uint64_t, wash::Vec3D>> expected;
    for (std::size_t j = 0; j < pos.size(); ++j) {
      if (j == i)
        continue;
      wash::Vec3D image = pos[j];
      for (int a = 0; a < 2; ++a) { // minimum image, computed independently
        double d = image.at(a) - pos[i].at(a), L = box.hi[a] - box.lo[a];
        if (d > L / 2)
          *image[a] -= L;
        else if (d < -L / 2)
          *image[a] += L;
      }
      if (withinRadius<3>(pos[i], image, r))
        expected.emplace_back(cells.keyOf(image), ids[j], image);
    }
    std::sort(expected.begin(), expected.end(), [](const auto &x, const auto &y) {
      return std::tie(std::get<0>(x), std::get<1>(x)) < std::tie(std::get<0>(y), std::get<1>(y));
    });
    ASSERT_EQ(found.size(), expected.size()) << "particle " << i;
    for (std::size_t n = 0; n < found.size(); ++n) {
      EXPECT_EQ(ids[found[n]], std::get<1>(expected[n]));
      EXPECT_EQ(images[n], std::get<2>(expected[n]));
    }
  }
}

TEST(Box, WrapsIntoTheBoxAndLeavesInsideCoordinatesAlone) {
  wash::detail::Box box;
  box.lo = {0.0, -1.0, 0.0};
  box.hi = {1.0, 1.0, 1.0};
  EXPECT_EQ(box.wrap(0.25, 0), 0.25);
  EXPECT_EQ(box.wrap(1.25, 0), 0.25);
  EXPECT_EQ(box.wrap(-0.5, 0), 0.5);
  EXPECT_EQ(box.wrap(-1.0, 1), -1.0);
  EXPECT_EQ(box.wrap(1.0, 1), -1.0);
  // Not finite: NaN, never a coordinate inside (the finite checks must see it).
  EXPECT_TRUE(std::isnan(box.wrap(std::nan(""), 0)));
  EXPECT_TRUE(std::isnan(box.wrap(INFINITY, 0)));
  EXPECT_TRUE(std::isnan(box.wrap(-INFINITY, 1)));
  EXPECT_EQ(box.image(0.9, 0.1, 0), -1);
  EXPECT_EQ(box.image(0.1, 0.9, 0), 1);
  EXPECT_EQ(box.image(0.4, 0.1, 0), 0);
  EXPECT_EQ(wash::detail::checkBox(box, 3, 0.3), ""); // not defined: nothing to check
  box.defined = true;
  box.periodic = {true, false, false};
  EXPECT_EQ(wash::detail::checkBox(box, 3, 0.3), "");
  EXPECT_NE(wash::detail::checkBox(box, 3, 0.5), ""); // L = 1 is not > 2r
}
