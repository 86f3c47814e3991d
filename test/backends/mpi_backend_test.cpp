// The MPI backend type (wash/mpi/backend.hpp) under mpirun: it has the
// interface the generated driver calls, and it distributes, searches and
// reduces over every rank's share.
#include <wash/backend/backend.hpp>
#include <wash/backend/frame_builder.hpp>
#include <wash/mpi/backend.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <string>

namespace {

static_assert(wash::backend::ParticleBackend<wash::mpi::Backend<2>>);
static_assert(wash::backend::ParticleBackend<wash::mpi::Backend<3>>);

using wash::backend::Index;

/// Creates 40 particles through the backend as create_particle does, x = 0..39
/// (plus `shift` on this rank), and returns how many rows it ever held.
std::size_t createLine(wash::mpi::Backend<2> &backend, wash::backend::MinimalParticles<2> &P,
                       double shift = 0.0) {
  std::size_t most = 0;
  for (std::uint64_t k = 0; k < 40; ++k) {
    const wash::Vec<double, 2> pos{double(k) + shift, 0.0};
    const std::uint64_t id = backend.create(P, 1.0, 1.0, 1.0, pos, pos);
    EXPECT_EQ(id, k); // the creation index, whichever rank keeps it
    P.id.push_back(id);
    P.pos.push_back(pos);
    most = std::max(most, P.size());
  }
  return most;
}

TEST(MpiBackend, EveryRankStoresItsBlocksAndReducesOverAll) {
  // Blocks of 4 creation indices, dealt round-robin: 10 blocks of 40 particles.
  setenv("WASH_MPI_CREATION_BLOCK", "4", 1);
  ASSERT_EQ(wash::mpi::Creations::blockSize(), 4u);
  const int me = wash::mpi::rank(), n = wash::mpi::ranks();
  std::size_t kept = 0;
  for (int block = me; block < 10; block += n)
    kept += 4;
  wash::mpi::Backend<2> backend;
  wash::backend::MinimalParticles<2> P;
  // Its own particles, and one scratch row for a particle another rank keeps.
  EXPECT_LE(createLine(backend, P), kept + 1);
  EXPECT_EQ(P.size(), kept + (9 % n == me ? 0 : 1)); // block 9 holds the last
  EXPECT_EQ(backend.distribute(P, [] { return 1.0; }), 40u);
  EXPECT_EQ(wash::mpi::allreduceSum(std::uint64_t(backend.owned().size())), 40u);
  EXPECT_EQ(backend.writes(), wash::mpi::rank() == 0);

  wash::detail::Box box;
  backend.search(P, wash::backend::fixedGeometry(1.5), box, [&](auto send) {
    send(P.id);
    send(P.pos);
  });
  std::vector<double> values(P.size(), 0.0);
  backend.forEachParticle([&](Index i) { values[i] = double(P.id[i]); });
  EXPECT_EQ(backend.reduce(P.id, values, wash::detail::ReduceOp::Sum), 780.0); // 0 + ... + 39
  // Exact: 1e16, then 38 ones, then -1e16 is 38 (added in id order it was 0),
  // and each rank sends one fixed-size state for it, whatever it holds.
  backend.forEachParticle([&](Index i) {
    values[i] = P.id[i] == 0 ? 1e16 : P.id[i] == 39 ? -1e16 : 1.0;
  });
  const std::uint64_t sent = wash::mpi::traffic().sums;
  EXPECT_EQ(backend.reduce(P.id, values, wash::detail::ReduceOp::Sum), 38.0);
  EXPECT_EQ(wash::mpi::traffic().sums - sent, sizeof(wash::detail::ExactSum::State));
  EXPECT_EQ(wash::mpi::Backend<2>::combineMax(double(wash::mpi::rank())),
            double(wash::mpi::ranks() - 1));
  // A frame stays on its rank (the output writes it collectively): its own
  // rows, which over all ranks are every particle once.
  wash::backend::FrameBuilder f(2, P.id, &backend.owned());
  const wash::detail::Frame mine = backend.gather(f.take());
  EXPECT_EQ(mine.size(), backend.owned().size());
  std::vector<std::uint64_t> ids = wash::mpi::allgatherv(mine.ids);
  std::sort(ids.begin(), ids.end());
  std::vector<std::uint64_t> every(40);
  std::iota(every.begin(), every.end(), std::uint64_t(0));
  EXPECT_EQ(ids, every);
}

TEST(MpiBackend, InitKernelsThatDifferAcrossRanksAreAnError) {
  const std::string message = "must be deterministic";
  { // a position differs on one rank
    wash::mpi::Backend<2> backend;
    wash::backend::MinimalParticles<2> P;
    createLine(backend, P, wash::mpi::rank() == 1 ? 1e-9 : 0.0);
    try {
      backend.distribute(P, [] { return 1.0; });
      ADD_FAILURE() << "different positions accepted";
    } catch (const wash::detail::RunError &e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
  { // one rank creates one more particle
    wash::mpi::Backend<2> backend;
    wash::backend::MinimalParticles<2> P;
    createLine(backend, P);
    if (wash::mpi::rank() == 0) {
      const wash::Vec<double, 2> pos{0.0, 0.0};
      P.id.push_back(backend.create(P, 1.0, 1.0, 1.0, pos, pos));
      P.pos.push_back(pos);
    }
    EXPECT_THROW(backend.distribute(P, [] { return 1.0; }), wash::detail::RunError);
  }
}

// A line of 40 particles one apart, x = id: particle 0 has a support radius
// of 10, every other one of 0.5, so the only pairs are (0, j) for j <= 10.
// Every rank's halo holds the particles its own pair with, and none further
// than one cell (1) beyond a pair's radius, although the search reaches 10.
void expectHaloOfPairs(bool symmetric) {
  setenv("WASH_MPI_CREATION_BLOCK", "4", 1);
  wash::mpi::Backend<2> backend;
  wash::backend::MinimalParticles<2> P;
  createLine(backend, P);
  backend.distribute(P, [] { return 1.0; });
  wash::backend::SearchGeometry at;
  at.reach = 10.0;
  at.support = 1.0; // radius = h
  at.symmetric = symmetric;
  auto radius = [](std::uint64_t id) { return id == 0 ? 10.0 : 0.5; };
  backend.search(
      P, at, wash::detail::Box{},
      [&](auto send) {
        send(P.id);
        send(P.pos);
      },
      [&P, &radius](Index row) { return radius(P.id[row]); });
  std::vector<char> isOwned(P.size(), 0);
  for (Index i : backend.owned())
    isOwned[i] = 1;
  std::vector<std::uint64_t> mine, ghosts;
  for (Index row = 0; row < P.size(); ++row)
    (isOwned[row] ? mine : ghosts).push_back(P.id[row]);
  // Within `slack` of a pair with one of this rank's particles.
  auto pairsWithMine = [&](std::uint64_t j, double slack) {
    for (std::uint64_t i : mine) {
      const double pair = symmetric ? std::max(radius(i), radius(j)) : radius(i);
      if (std::abs(double(i) - double(j)) <= pair + slack)
        return true;
    }
    return false;
  };
  for (std::uint64_t j = 0; j < 40; ++j)
    if (std::find(mine.begin(), mine.end(), j) == mine.end() && pairsWithMine(j, 0.0))
      EXPECT_NE(std::find(ghosts.begin(), ghosts.end(), j), ghosts.end())
          << "rank " << wash::mpi::rank() << " lacks particle " << j;
  for (std::uint64_t j : ghosts)
    EXPECT_TRUE(pairsWithMine(j, 1.0)) << "rank " << wash::mpi::rank() << " holds particle " << j
                                       << ", which pairs with none of its own";
}

TEST(MpiBackend, AHaloHoldsWhatPairsReachUnderTheSymmetricRule) { expectHaloOfPairs(true); }
TEST(MpiBackend, AHaloHoldsWhatPairsReachUnderTheGatherRule) { expectHaloOfPairs(false); }

} // namespace
