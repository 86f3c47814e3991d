// The canonical cell coordinate (wash/detail/cell.hpp), which every runtime's
// cells come from: the neighbour order depends on it to the last bit.
#include <wash/detail/cell.hpp>
#include <wash/detail/neighbour_search.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using wash::detail::cellCoordinate;

TEST(CellCoordinate, FloorsTowardsMinusInfinity) {
  EXPECT_EQ(cellCoordinate(0.5, 1.0), 0);
  EXPECT_EQ(cellCoordinate(1.0, 1.0), 1); // a border belongs to the cell above
  EXPECT_EQ(cellCoordinate(-0.5, 1.0), -1);
  EXPECT_EQ(cellCoordinate(-1.0, 1.0), -1);
  EXPECT_EQ(cellCoordinate(0.0, 0.35), 0);
  EXPECT_EQ(cellCoordinate(-0.0, 0.35), 0);
  EXPECT_EQ(cellCoordinate(-1e-320, 0.35), -1); // a denormal below 0 is in cell -1
  EXPECT_EQ(cellCoordinate(1.05, 0.35), 3);     // 1.05 / 0.35 is 3.0000000000000004
}

// The quotient as rounded, then floored: 0.3 / 0.1 is 2.9999999999999996 in
// double, so 0.3 lies in cell 2, although 0.3 * (1 / 0.1) rounds to 3.
TEST(CellCoordinate, IsTheRoundedQuotientFloored) {
  ASSERT_EQ(0.3 * (1.0 / 0.1), 3.0);
  EXPECT_EQ(cellCoordinate(0.3, 0.1), 2);
  EXPECT_EQ(cellCoordinate(-0.3, 0.1), -3);
  EXPECT_EQ(cellCoordinate(0.7, 0.1), 6);
}

TEST(CellCoordinate, TheReferenceCellListKeysByIt) {
  wash::detail::CellList<2> cells;
  std::vector<wash::Vec2D> pos{{0.3, -0.05}};
  std::vector<std::uint64_t> ids{0};
  cells.build(pos, ids, 0.1);
  // Slowest axis first: (y, x).
  EXPECT_EQ(cells.keyOf(pos[0]), (wash::detail::CellList<2>::Key{-1, 2}));
}
