// The MPI backend type (wash/mpi/backend.hpp) under mpirun: it has the
// interface the generated driver calls, and it distributes, searches and
// reduces over every rank's share.
#include <wash/backend/backend.hpp>
#include <wash/backend/frame_builder.hpp>
#include <wash/mpi/backend.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

namespace {

static_assert(wash::backend::ParticleBackend<wash::mpi::Backend<2>>);
static_assert(wash::backend::ParticleBackend<wash::mpi::Backend<3>>);

using wash::backend::Index;

TEST(MpiBackend, EveryRankKeepsAShareAndReducesOverAll) {
  wash::mpi::Backend<2> backend;
  wash::backend::MinimalParticles<2> P; // every rank creates the same 40 particles
  for (std::size_t k = 0; k < 40; ++k) {
    P.id.push_back(k);
    P.pos.push_back(wash::Vec<double, 2>{double(k), 0.0});
  }
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

} // namespace
