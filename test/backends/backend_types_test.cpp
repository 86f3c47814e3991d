// Every backend type of backends.def has the interface the generated driver
// calls (ParticleBackend), and every runtime name the emitters spell
// (translator/include/wash/translator/Emit/RuntimeNames.def) exists: renaming
// one in the runtime fails this file's build.
#include <wash/backend/backend.hpp>
#include <wash/backend/program.hpp>
#include <wash/openmp/backend.hpp>
#include <wash/serial/backend.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <omp.h>
#include <string>

namespace runtime_names {
#define WASH_RUNTIME_NAME(Id, Qualified) using Qualified;
#include "wash/translator/Emit/RuntimeNames.def"
#undef WASH_RUNTIME_NAME
} // namespace runtime_names

static_assert(wash::backend::ParticleBackend<wash::serial::Backend<2>>);
static_assert(wash::backend::ParticleBackend<wash::serial::Backend<3>>);
static_assert(wash::backend::ParticleBackend<wash::openmp::Backend<2>>);
static_assert(wash::backend::ParticleBackend<wash::openmp::Backend<3>>);

namespace {

using wash::backend::Index;

/// Particles on a line, x = 0, 1, ..., n-1, ids in reverse order.
template <typename Backend> wash::backend::MinimalParticles<2> line(std::size_t n) {
  wash::backend::MinimalParticles<2> P;
  for (std::size_t k = 0; k < n; ++k) {
    P.id.push_back(n - 1 - k);
    P.pos.push_back(wash::Vec<double, 2>{double(k), 0.0});
  }
  return P;
}

template <typename Backend> void searchesAndLoops() {
  Backend backend;
  auto P = line<Backend>(10);
  EXPECT_EQ(backend.distribute(P, [] { return 1.0; }), 10u);
  EXPECT_EQ(backend.owned().size(), 10u);
  wash::detail::Box box; // unbounded: no images
  backend.search(P, wash::backend::fixedGeometry(1.5), box, wash::backend::NoColumns{});
  // The search sorts by (cell, id) (docs/semantics.md).
  auto cell = [&](std::size_t k) { return std::floor(P.pos[k].at(0) / 1.5); };
  for (std::size_t k = 1; k < P.size(); ++k)
    EXPECT_TRUE(cell(k - 1) < cell(k) || (cell(k - 1) == cell(k) && P.id[k - 1] < P.id[k]))
        << "row " << k;
  std::vector<int> visits(P.size(), 0);
  backend.forEachParticle([&](Index i) { ++visits[i]; });
  EXPECT_EQ(std::accumulate(visits.begin(), visits.end(), 0), 10);
  EXPECT_FALSE(backend.forEachParticleChecked([](Index i) { return i != 3; }));
  EXPECT_TRUE(backend.forEachParticleChecked([](Index) { return true; }));
  std::vector<double> values(P.size());
  for (Index i = 0; i < P.size(); ++i)
    values[i] = double(P.id[i]);
  EXPECT_EQ(backend.reduce(P.id, values, wash::detail::ReduceOp::Sum), 45.0);
  EXPECT_EQ(backend.reduce(P.id, values, wash::detail::ReduceOp::Max), 9.0);
  EXPECT_EQ(Backend::combineMax(2.5), 2.5); // one process: its own maximum
  EXPECT_TRUE(backend.writes());
}

TEST(BackendTypes, OpenMPSumsAreExactAtEveryThreadCount) {
  // Values whose sum in any order loses bits: every thread count, and the
  // serial loop, must give the reference's exact sum, bit for bit.
  std::vector<double> values;
  std::vector<Index> rows;
  for (Index k = 0; k < 100000; ++k) {
    values.push_back(k % 3 == 0 ? 1e300 * (k % 2 ? -1 : 1) : // +-1e300s cancel
                         std::ldexp(1.0 + k, -40 - int(k % 50)));
    rows.push_back(k);
  }
  const double expected = wash::detail::reduceInIdOrder(values, wash::detail::ReduceOp::Sum);
  EXPECT_NE(expected, 0.0);
  EXPECT_EQ(wash::serial::Loop::sum(values, rows).round<double>(), expected);
  const int most = omp_get_max_threads();
  for (int threads : {1, 2, 3, 4, 7}) {
    omp_set_num_threads(threads);
    EXPECT_EQ(wash::openmp::Loop::sum(values, rows).round<double>(), expected) << threads;
  }
  omp_set_num_threads(most);
}

TEST(BackendTypes, SerialSearchesLoopsAndReduces) { searchesAndLoops<wash::serial::Backend<2>>(); }
TEST(BackendTypes, OpenMPSearchesLoopsAndReduces) { searchesAndLoops<wash::openmp::Backend<2>>(); }

/// Storage whose `mass` is rewritten after every search before anything
/// reads it, as the generated header marks it (forEachReorderedColumn).
struct ReorderingFewer : wash::backend::MinimalParticles<2> {
  wash::backend::Column<double> mass;
  template <typename F> void forEachColumn(F f) {
    MinimalParticles::forEachColumn(f);
    f(mass);
  }
  template <typename F> void forEachReorderedColumn(F f) { MinimalParticles::forEachColumn(f); }
};

TEST(BackendTypes, TheSharedMemorySortLeavesRewrittenColumnsInTheOldOrder) {
  wash::serial::Backend<2> backend;
  ReorderingFewer P;
  for (std::size_t k = 0; k < 4; ++k) { // descending x: the sort reverses them
    P.id.push_back(k);
    P.pos.push_back(wash::Vec<double, 2>{double(3 - k) * 2.0, 0.0});
    P.mass.push_back(double(k));
  }
  backend.distribute(P, [] { return 1.0; });
  backend.search(P, wash::backend::fixedGeometry(1.0), wash::detail::Box{},
                 wash::backend::NoColumns{});
  EXPECT_EQ(P.id, (std::vector<std::uint64_t>{3, 2, 1, 0}));
  EXPECT_EQ(P.mass, (std::vector<double>{0, 1, 2, 3})); // not moved
}

// 40 particles one apart across a box periodic in x, [0, 40): the last
// (x = 39.5) has a support radius of 10, every other one 0.5, so the only
// pairs across the face are the last with the first ten. Images reach as far
// as pairs do: those ten have images by the high face, and the particles
// near the high face that pair with nothing across it have none (they had,
// when images reached the largest radius on every face).
template <typename Backend> void imagesOfPairs(bool symmetric) {
  Backend backend;
  wash::backend::MinimalParticles<2> P;
  for (std::uint64_t k = 0; k < 40; ++k) {
    P.id.push_back(k);
    P.pos.push_back(wash::Vec<double, 2>{double(k) + 0.5, 0.5});
  }
  backend.distribute(P, [] { return 1.0; });
  wash::detail::Box box;
  ASSERT_TRUE(wash::detail::setBox(box, 2, {0.0, 0.0}, {40.0, 1.0}, {true, false}));
  wash::backend::SearchGeometry at;
  at.reach = 10.0;
  at.cellSize = 2.5;
  at.support = 1.0; // radius = h
  at.symmetric = symmetric;
  auto radius = [](std::uint64_t id) { return id == 39 ? 10.0 : 0.5; };
  backend.search(P, at, box, wash::backend::NoColumns{},
                 [&P, &radius](Index row) { return radius(P.id[row]); });
  std::vector<int> rows(40, 0);
  for (Index k = 0; k < P.size(); ++k)
    ++rows[P.id[k]];
  for (std::uint64_t j = 0; j < 10; ++j)
    EXPECT_EQ(rows[j], 2) << "particle " << j << " pairs with 39 across the face";
  for (std::uint64_t j = 10; j < 39; ++j)
    EXPECT_EQ(rows[j], 1) << "particle " << j << " pairs with nothing across the face";
  if (symmetric)
    EXPECT_EQ(rows[39], 2) << "39's own radius reaches across the face";
}

TEST(BackendTypes, ImagesReachAsFarAsPairsUnderTheSymmetricRule) {
  imagesOfPairs<wash::serial::Backend<2>>(true);
  imagesOfPairs<wash::openmp::Backend<2>>(true);
}

TEST(BackendTypes, ImagesReachAsFarAsPairsUnderTheGatherRule) {
  imagesOfPairs<wash::serial::Backend<2>>(false);
  imagesOfPairs<wash::openmp::Backend<2>>(false);
}

TEST(BackendTypes, NamesAreTheBackendsDefNames) {
  EXPECT_EQ(std::string(wash::serial::Backend<2>::name), "serial");
  EXPECT_EQ(std::string(wash::openmp::Backend<2>::name), "openmp");
}

} // namespace
