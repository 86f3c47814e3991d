// Unit tests of the MPI domain's balance (wash/mpi/domain.hpp), run under
// mpirun at several rank counts: every rank runs every test in the same order,
// so the collectives match.
#include <wash/mpi/domain.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace {

using wash::mpi::Domain;
using wash::mpi::rank;
using wash::mpi::ranks;

// The work each rank gets under `domain`, summed over all ranks: this rank's
// particles (keys) share its measured `work` in proportion to the number of
// particles in their cell, the model Domain::balance is documented to use.
std::vector<double> workPerOwner(const Domain<2> &domain, const std::vector<std::uint64_t> &keys,
                                 double work) {
  std::map<std::uint64_t, double> population;
  for (std::uint64_t k : keys)
    population[k] += 1.0;
  double weights = 0.0;
  for (std::uint64_t k : keys)
    weights += population[k];
  std::vector<double> local(ranks(), 0.0), total(ranks());
  for (std::uint64_t k : keys)
    local[domain.ownerOf(k)] += work * population[k] / weights;
  for (int r = 0; r < ranks(); ++r)
    total[r] = wash::mpi::allreduceSum(local[r]);
  return total;
}

// Rank r holds keys [1000 r, 1000 r + 1000), one particle per key.
std::vector<std::uint64_t> blockOfKeys() {
  std::vector<std::uint64_t> keys;
  for (std::uint64_t k = 0; k < 1000; ++k)
    keys.push_back(1000 * std::uint64_t(rank()) + k);
  return keys;
}

std::size_t keptOwn(const Domain<2> &domain, const std::vector<std::uint64_t> &keys) {
  std::size_t kept = 0;
  for (std::uint64_t k : keys)
    kept += domain.ownerOf(k) == rank();
  return kept;
}

TEST(MpiDomain, EqualWorkKeepsEveryBlockInPlace) {
  Domain<2> domain;
  const std::vector<std::uint64_t> keys = blockOfKeys();
  domain.balance(keys, 1.0);
  EXPECT_NEAR(double(keptOwn(domain, keys)), 1000.0, 2.0);
  for (double w : workPerOwner(domain, keys, 1.0))
    EXPECT_NEAR(w, 1.0, 0.01);
}

TEST(MpiDomain, ASlowerRankGivesParticlesAway) {
  Domain<2> domain;
  const std::vector<std::uint64_t> keys = blockOfKeys();
  // Rank 0 took three times as long as the others for as many particles.
  const double work = rank() == 0 ? 3.0 : 1.0;
  domain.balance(keys, work);
  const double share = (3.0 + (ranks() - 1)) / ranks();
  for (double w : workPerOwner(domain, keys, work))
    EXPECT_NEAR(w, share, 0.01);
  if (rank() == 0)
    EXPECT_NEAR(double(keptOwn(domain, keys)), share / 3.0 * 1000.0, 3.0);
}

TEST(MpiDomain, CrowdedCellsWeighMoreThanLoneParticles) {
  Domain<2> domain;
  // Rank 0: ten cells of 50 particles (keys 0..9), then 500 lone particles;
  // it was twice as busy as each other rank, whose particles are all alone.
  std::vector<std::uint64_t> keys;
  double work = 1.0;
  if (rank() == 0) {
    work = 2.0;
    for (std::uint64_t cell = 0; cell < 10; ++cell)
      for (int k = 0; k < 50; ++k)
        keys.push_back(cell);
    for (std::uint64_t k = 10; k < 510; ++k)
      keys.push_back(k);
  } else {
    keys = blockOfKeys();
  }
  domain.balance(keys, work);
  // Each rank ends with its share of the work, give or take one crowded cell
  // (cells are never split: 2 * 2500 / 25500 of rank 0's work each).
  const double share = (2.0 + (ranks() - 1)) / ranks();
  for (double w : workPerOwner(domain, keys, work))
    EXPECT_NEAR(w, share, 0.25);
  // Counting particles instead would leave rank 0 with share / 2 of its 1000
  // particles (500 or more); the crowded cells hold nearly all of its work.
  if (rank() == 0)
    EXPECT_LT(keptOwn(domain, keys), 450u);
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
