// The backends' cell grid and neighbour ranges must give the reference's
// neighbours in the reference's canonical order, whatever the storage order.
#include <wash/backend/neighbours.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/detail/neighbour_search.hpp>

#include "scan_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace wash::backend;

namespace {

/// Neighbour ids of every particle (by id) from the backend, after the sort.
template <int D, typename PosT>
std::vector<std::vector<std::uint64_t>> backendNeighbours(Column<PosT> pos,
                                                          Column<std::uint64_t> id, double r) {
  CellGrid<D> grid;
  std::vector<Index> order;
  grid.sort(pos, id, r, order);
  permute(pos, order);
  permute(id, order);
  std::vector<std::vector<std::uint64_t>> out(pos.size());
  for (Index i = 0; i < pos.size(); ++i) {
    Neighbours<D, PosT> neighbours(grid, pos, i);
    for (const NeighbourRef &n : neighbours)
      out[id[i]].push_back(id[n]);
    EXPECT_EQ(neighbours.size(), out[id[i]].size());
  }
  return out;
}

/// The same from the reference runtime's cell list.
template <int D, typename PosT>
std::vector<std::vector<std::uint64_t>>
referenceNeighbours(const Column<PosT> &pos, const Column<std::uint64_t> &id, double r) {
  std::vector<wash::Vec<double, D>> p;
  for (const PosT &v : pos)
    p.emplace_back(v);
  wash::detail::CellList<D> cells;
  cells.build(p, id, r);
  std::vector<std::vector<std::uint64_t>> out(pos.size());
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < p.size(); ++i) {
    cells.neighbours(i, found);
    for (std::size_t j : found)
      out[id[i]].push_back(id[j]);
  }
  return out;
}

template <int D, typename T>
void compareOnRandomCloud(unsigned seed, int n, double extent, double r) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-extent, extent);
  Column<wash::Vec<T, D>> pos;
  Column<std::uint64_t> id;
  for (int k = 0; k < n; ++k) {
    wash::Vec<T, D> v;
    for (int a = 0; a < D; ++a)
      *v[a] = T(u(rng));
    pos.push_back(v);
    id.push_back(std::uint64_t((k * 7919) % n)); // storage order is not id order
  }
  EXPECT_EQ((backendNeighbours<D>(pos, id, r)), (referenceNeighbours<D>(pos, id, r)));
}

} // namespace

TEST(CellGrid, MatchesTheReferenceIn2D) {
  onEveryScanPath([] { compareOnRandomCloud<2, double>(1, 1500, 3.0, 0.35); });
}
TEST(CellGrid, MatchesTheReferenceIn3D) {
  onEveryScanPath([] { compareOnRandomCloud<3, double>(2, 1500, 1.0, 0.2); });
}
TEST(CellGrid, MatchesTheReferenceWithFloatPositions) {
  onEveryScanPath([] { compareOnRandomCloud<2, float>(3, 1000, 2.0, 0.3); });
  onEveryScanPath([] { compareOnRandomCloud<3, float>(6, 1000, 1.0, 0.2); });
}

TEST(CellGrid, LatticeOnCellBorders) {
  Column<wash::Vec2D> pos;
  Column<std::uint64_t> id;
  for (int y = -5; y <= 5; ++y)
    for (int x = -5; x <= 5; ++x) {
      pos.push_back({x * 0.25, y * 0.25});
      id.push_back(id.size());
    }
  onEveryScanPath([&] {
    EXPECT_EQ((backendNeighbours<2>(pos, id, 0.5)), (referenceNeighbours<2>(pos, id, 0.5)));
  });
}

namespace {

/// Cell sizes whose borders k * size are inexact in binary, and two that are.
constexpr double cellSizes[] = {0.35, 0.1, 1.0 / 3.0, 0.7, 1e-3, 37.5, 0.2 * 1.5, 3e-7};

/// An empty grid with cells of `size`: enough to ask it for cells.
CellGrid<2> gridOfSize(double size) {
  CellGrid<2> grid;
  Column<wash::Vec2D> none;
  Column<std::uint64_t> noIds;
  std::vector<Index> order;
  grid.sort(none, noIds, size, order);
  return grid;
}

/// Coordinates where a multiplication and a division may floor apart: the
/// borders k * size of 6001 cells, k * size +- size (a scan's p - r and p + r
/// for particles on a border), three floating-point steps either way of each;
/// then 20000 random ones.
std::vector<double> bordersAndMore(double size, std::mt19937_64 &rng) {
  std::vector<double> xs;
  for (std::int64_t k = -3000; k <= 3000; ++k) {
    const double border = double(k) * size;
    for (double x : {border, border + size, border - size}) {
      double up = x, down = x;
      for (int n = 0; n < 3;
           ++n, up = std::nextafter(up, 1e300), down = std::nextafter(down, -1e300))
        xs.push_back(up), xs.push_back(down);
    }
  }
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int k = 0; k < 20000; ++k)
    xs.push_back(unit(rng) * 1e4 * size);
  return xs;
}

} // namespace

// The grid finds cells by multiplying with the inverse cell size; it must
// still give floor(x / size) exactly, the canonical cell (cellCoordinate), on
// and around every cell border, where the product and the quotient round apart.
TEST(CellGrid, CellCoordinateIsTheQuotientFloored) {
  std::mt19937_64 rng(7);
  std::size_t checked = 0;
  for (double size : cellSizes) {
    const CellGrid<2> grid = gridOfSize(size);
    std::vector<double> xs = bordersAndMore(size, rng);
    xs.insert(xs.end(), {0.0, -0.0, 1e-320, -1e-320, 1e15, -1e15, 4.5e15 * size});
    for (double x : xs) {
      ASSERT_EQ(grid.coordinate(x), wash::detail::cellCoordinate(x, size))
          << "x = " << x << ", cell size " << size;
      ++checked;
    }
  }
  EXPECT_GT(checked, 200000u);
}

// A scan with the cell size as radius takes the cells before and after the
// particle's from one product; they must be those of x - r and x + r divided.
TEST(CellGrid, NeighbourCellsAreThoseOfTheIntervalsEnds) {
  std::mt19937_64 rng(8);
  std::size_t fast = 0, slow = 0;
  for (double size : cellSizes) {
    const CellGrid<2> grid = gridOfSize(size);
    for (double x : bordersAndMore(size, rng)) {
      std::int64_t first, last;
      if (!grid.neighbourCells(x, size, first, last)) {
        ++slow;
        continue;
      }
      ++fast;
      ASSERT_EQ(first, wash::detail::cellCoordinate(x - size, size)) << "x = " << x;
      ASSERT_EQ(last, wash::detail::cellCoordinate(x + size, size)) << "x = " << x;
    }
    std::int64_t first, last;
    EXPECT_FALSE(grid.neighbourCells(0.5 * size, 0.5 * size, first, last)) << "another radius";
  }
  EXPECT_GT(fast, 150000u); // the random ones, mostly
  EXPECT_GT(slow, 50000u);  // the borders
}

TEST(CellGrid, SortPutsCellsInRowOrderAndIdsAscendingInside) {
  Column<wash::Vec2D> pos{{1.5, 0.2}, {0.2, 0.2}, {0.3, 1.1}, {0.1, 0.1}};
  Column<std::uint64_t> id{0, 3, 1, 2};
  CellGrid<2> grid;
  std::vector<Index> order;
  grid.sort(pos, id, 1.0, order);
  // cell (0,0): ids 2, 3; cell (1,0): id 0; cell (0,1): id 1.
  EXPECT_EQ(order, (std::vector<Index>{3, 1, 0, 2}));
}

// The smoothing-length rule: neighbours within each particle's own radius, in
// id order, whatever cell size the backend picks.
namespace {

using Lists = std::vector<std::vector<std::uint64_t>>;

template <int D> struct RadiusCloud {
  Column<wash::Vec<double, D>> pos;
  Column<std::uint64_t> id;
  Column<double> h;
};

template <int D>
RadiusCloud<D> radiusCloud(unsigned seed, int n, double extent, double hMin, double hMax) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-extent, extent), uh(hMin, hMax);
  RadiusCloud<D> c;
  for (int k = 0; k < n; ++k) {
    wash::Vec<double, D> v;
    for (int a = 0; a < D; ++a)
      *v[a] = u(rng);
    c.pos.push_back(v);
    c.id.push_back(std::uint64_t((k * 7919) % n));
    c.h.push_back(uh(rng));
  }
  return c;
}

std::size_t pairs(const Lists &lists) {
  std::size_t n = 0;
  for (const auto &l : lists)
    n += l.size();
  return n;
}

template <int D> Lists bruteForce(const RadiusCloud<D> &c, double support) {
  Lists out(c.pos.size());
  for (std::size_t i = 0; i < c.pos.size(); ++i) {
    std::vector<std::pair<std::uint64_t, std::size_t>> hits;
    for (std::size_t j = 0; j < c.pos.size(); ++j)
      if (j != i && wash::detail::withinRadius<D>(c.pos[i], c.pos[j], support * c.h[i]))
        hits.push_back({c.id[j], j});
    std::sort(hits.begin(), hits.end());
    for (auto [id, j] : hits)
      out[c.id[i]].push_back(id);
  }
  return out;
}

template <int D> Lists backendLists(RadiusCloud<D> c, double support) {
  std::vector<Index> rows(c.pos.size());
  for (Index i = 0; i < rows.size(); ++i)
    rows[i] = i;
  const SearchGeometry g =
      smoothingGeometry(support, c.h, c.id, rows, wash::detail::Box{}, D, 1, "test");
  CellGrid<D> grid;
  std::vector<Index> order;
  grid.sort(c.pos, c.id, g.cellSize, order);
  permute(c.pos, order);
  permute(c.id, order);
  permute(c.h, order);
  Lists out(c.pos.size());
  for (Index i = 0; i < c.pos.size(); ++i)
    for (const NeighbourRef &n :
         Neighbours<D, wash::Vec<double, D>>(grid, c.pos, i, c.id, g.radiusOf(c.h[i])))
      out[c.id[i]].push_back(c.id[n]);
  return out;
}

template <int D> Lists referenceLists(const RadiusCloud<D> &c, double support) {
  std::vector<wash::Vec<double, D>> p(c.pos.begin(), c.pos.end());
  double largest = 0;
  for (double h : c.h)
    largest = std::max(largest, support * h);
  wash::detail::CellList<D> cells;
  cells.build(p, c.id, largest);
  Lists out(p.size());
  std::vector<std::size_t> found;
  for (std::size_t i = 0; i < p.size(); ++i) {
    cells.neighbours(i, support * c.h[i], true, found);
    for (std::size_t j : found)
      out[c.id[i]].push_back(c.id[j]);
  }
  return out;
}

} // namespace

TEST(SmoothingLengthSearch, BackendAndReferenceMatchBruteForce3D) {
  // Radii from 0.04 to 0.4: the backend's cells are a quarter of the largest.
  RadiusCloud<3> c = radiusCloud<3>(4, 1200, 1.0, 0.02, 0.2);
  Lists exact = bruteForce(c, 2.0);
  ASSERT_GT(pairs(exact), 5000u);
  onEveryScanPath([&] { EXPECT_EQ(backendLists(c, 2.0), exact); });
  EXPECT_EQ(referenceLists(c, 2.0), exact);
}

TEST(SmoothingLengthSearch, BackendAndReferenceMatchBruteForce2D) {
  RadiusCloud<2> c = radiusCloud<2>(5, 1500, 2.0, 0.1, 0.15); // nearly uniform radii
  Lists exact = bruteForce(c, 2.0);
  ASSERT_GT(pairs(exact), 10000u);
  onEveryScanPath([&] { EXPECT_EQ(backendLists(c, 2.0), exact); });
  EXPECT_EQ(referenceLists(c, 2.0), exact);
}

TEST(SmoothingLengthSearch, GeometryRejectsNegativeSmoothingLength) {
  Column<double> h{0.1, -0.5};
  Column<std::uint64_t> id{0, 1};
  std::vector<Index> rows{0, 1};
  try {
    smoothingGeometry(2.0, h, id, rows, wash::detail::Box{}, 2, 7, "Density");
    FAIL() << "a negative smoothing length was accepted";
  } catch (const wash::detail::RunError &e) {
    EXPECT_NE(std::string(e.what()).find("step 7: kernel 'Density': particle 1:"),
              std::string::npos)
        << e.what();
  }
}

TEST(SmoothingLengthSearch, GeometryRejectsSupportOverHalfAPeriodicBox) {
  wash::detail::Box box;
  ASSERT_TRUE(wash::detail::setBox(box, 2, {0, 0}, {1, 1}, {true, false}));
  Column<double> h{0.1, 0.3};
  Column<std::uint64_t> id{0, 1};
  std::vector<Index> rows{0, 1};
  EXPECT_THROW(smoothingGeometry(2.0, h, id, rows, box, 2, 1, "K"), wash::detail::RunError);
  h[1] = 0.2;
  EXPECT_DOUBLE_EQ(smoothingGeometry(2.0, h, id, rows, box, 2, 1, "K").reach, 0.4);
}
