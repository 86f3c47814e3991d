// The backends' cell grid and neighbour ranges must give the reference's
// neighbours in the reference's canonical order, whatever the storage order.
#include <wash/backend/neighbours.hpp>
#include <wash/detail/neighbour_search.hpp>

#include <gtest/gtest.h>

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

template <int D, typename T> void compareOnRandomCloud(unsigned seed, int n, double extent, double r) {
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

TEST(CellGrid, MatchesTheReferenceIn2D) { compareOnRandomCloud<2, double>(1, 1500, 3.0, 0.35); }
TEST(CellGrid, MatchesTheReferenceIn3D) { compareOnRandomCloud<3, double>(2, 1500, 1.0, 0.2); }
TEST(CellGrid, MatchesTheReferenceWithFloatPositions) {
  compareOnRandomCloud<2, float>(3, 1000, 2.0, 0.3);
}

TEST(CellGrid, LatticeOnCellBorders) {
  Column<wash::Vec2D> pos;
  Column<std::uint64_t> id;
  for (int y = -5; y <= 5; ++y)
    for (int x = -5; x <= 5; ++x) {
      pos.push_back({x * 0.25, y * 0.25});
      id.push_back(id.size());
    }
  EXPECT_EQ((backendNeighbours<2>(pos, id, 0.5)), (referenceNeighbours<2>(pos, id, 0.5)));
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
