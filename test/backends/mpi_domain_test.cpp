// Unit tests of the MPI domain's balance (wash/mpi/domain.hpp), run under
// mpirun at several rank counts: every rank runs every test in the same order,
// so the collectives match.
#include <wash/mpi/domain.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace {

using wash::mpi::Domain;
using wash::mpi::rank;
using wash::mpi::ranks;
using Cell = Domain<2>::Cell;

// The work each rank gets under `domain`, summed over all ranks: this rank's
// particles (cells) share its measured `work` in proportion to the number of
// particles in their cell, the model Domain::balance is documented to use.
std::vector<double> workPerOwner(const Domain<2> &domain, const std::vector<Cell> &cells,
                                 double work) {
  std::map<Cell, double> population;
  for (const Cell &c : cells)
    population[c] += 1.0;
  double weights = 0.0;
  for (const Cell &c : cells)
    weights += population[c];
  std::vector<double> local(ranks(), 0.0), total(ranks());
  for (const Cell &c : cells)
    local[domain.ownerOf(c)] += work * population[c] / weights;
  for (int r = 0; r < ranks(); ++r)
    total[r] = wash::mpi::allreduceSum(local[r]);
  return total;
}

// Rank r holds the cells [100 r, 100 r + 100) x [0, 10), one particle each:
// together a strip the bisection cuts across its length.
std::vector<Cell> blockOfCells() {
  std::vector<Cell> cells;
  for (std::int64_t y = 0; y < 10; ++y)
    for (std::int64_t x = 0; x < 100; ++x)
      cells.push_back({100 * rank() + x, y});
  return cells;
}

std::size_t keptOwn(const Domain<2> &domain, const std::vector<Cell> &cells) {
  std::size_t kept = 0;
  for (const Cell &c : cells)
    kept += domain.ownerOf(c) == rank();
  return kept;
}

TEST(MpiDomain, EqualWorkKeepsEveryBlockInPlace) {
  Domain<2> domain;
  const std::vector<Cell> cells = blockOfCells();
  domain.balance(cells, 1.0);
  EXPECT_NEAR(double(keptOwn(domain, cells)), 1000.0, 20.0);
  for (double w : workPerOwner(domain, cells, 1.0))
    EXPECT_NEAR(w, 1.0, 0.03);
}

TEST(MpiDomain, ASlowerRankGivesParticlesAway) {
  Domain<2> domain;
  const std::vector<Cell> cells = blockOfCells();
  // Rank 0 took three times as long as the others for as many particles.
  const double work = rank() == 0 ? 3.0 : 1.0;
  domain.balance(cells, work);
  const double share = (3.0 + (ranks() - 1)) / ranks();
  for (double w : workPerOwner(domain, cells, work))
    EXPECT_NEAR(w, share, 0.05 * share);
  if (rank() == 0)
    EXPECT_NEAR(double(keptOwn(domain, cells)), share / 3.0 * 1000.0, 30.0);
}

TEST(MpiDomain, CrowdedCellsWeighMoreThanLoneParticles) {
  Domain<2> domain;
  // Rank 0: ten cells of 50 particles, then 500 lone particles, in its block;
  // it was twice as busy as each other rank, whose particles are all alone.
  std::vector<Cell> cells;
  double work = 1.0;
  if (rank() == 0) {
    work = 2.0;
    for (std::int64_t x = 0; x < 10; ++x)
      for (int k = 0; k < 50; ++k)
        cells.push_back({x, 0});
    for (std::int64_t k = 0; k < 500; ++k)
      cells.push_back({10 + k % 90, 1 + k / 90});
  } else {
    cells = blockOfCells();
  }
  domain.balance(cells, work);
  // Each rank ends with its share of the work, give or take the crowded cells
  // of one column (cells are never split: 2 * 2500 / 25500 of rank 0's work each).
  const double share = (2.0 + (ranks() - 1)) / ranks();
  for (double w : workPerOwner(domain, cells, work))
    EXPECT_NEAR(w, share, 0.25);
  // Counting particles instead would leave rank 0 with share / 2 of its 1000
  // particles (500 or more); the crowded cells hold nearly all of its work.
  if (rank() == 0)
    EXPECT_LT(keptOwn(domain, cells), 450u);
}

// Pieces are boxes of cells with a share of them each, at any rank count;
// four ranks on a square get its quadrants, each a box half the square's
// side.
TEST(MpiDomain, BisectionCutsBoxes) {
  Domain<2> domain;
  // Rank r: an equal band of the rows of a 64 x 64 square, one particle a cell.
  const std::int64_t side = 64, n = ranks();
  std::vector<Cell> cells;
  for (std::int64_t y = side * rank() / n; y < side * (rank() + 1) / n; ++y)
    for (std::int64_t x = 0; x < side; ++x)
      cells.push_back({x, y});
  domain.balance(cells, 1.0);
  std::vector<std::int64_t> count(n, 0), lo(2 * n, side), hi(2 * n, -1); // x and y per owner
  for (std::int64_t y = 0; y < side; ++y)
    for (std::int64_t x = 0; x < side; ++x) {
      const int r = domain.ownerOf({x, y});
      ++count[r];
      lo[2 * r] = std::min(lo[2 * r], x), hi[2 * r] = std::max(hi[2 * r], x);
      lo[2 * r + 1] = std::min(lo[2 * r + 1], y), hi[2 * r + 1] = std::max(hi[2 * r + 1], y);
    }
  for (int r = 0; r < n; ++r) {
    const std::int64_t width = hi[2 * r] - lo[2 * r] + 1, height = hi[2 * r + 1] - lo[2 * r + 1] + 1;
    EXPECT_EQ(width * height, count[r]) << "owner " << r << "'s cells are not a box";
    EXPECT_NEAR(double(count[r]), double(side * side) / double(n), 0.05 * side * side / n)
        << "owner " << r;
    if (n == 4) {
      EXPECT_NEAR(double(width), 32.0, 2.0) << "owner " << r;
      EXPECT_NEAR(double(height), 32.0, 2.0) << "owner " << r;
    }
  }
}

// The domain's cells are the canonical ones (wash/detail/cell.hpp): 0.3 / 0.1
// rounds below 3, so 0.3 lies in cell 2.
TEST(MpiDomain, CellsAreTheCanonicalCells) {
  Domain<2> domain;
  domain.setCellSize(0.1);
  EXPECT_EQ(domain.cellOf({0.3, -0.05}), (Domain<2>::Cell{2, -1}));
}

} // namespace

int main(int argc, char **argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
