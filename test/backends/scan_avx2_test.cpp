// The AVX2 neighbour scan must keep exactly the candidates the scalar scan
// keeps, in the same order: the same squared distances, ties at the radius
// included, the particle itself left out, rows ending anywhere in a block and
// at the end of the column. (Neighbours and the reference agree in
// cell_grid_test.cpp, which on an AVX2 machine runs this path too.)
#include <wash/backend/neighbours.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

using namespace wash::backend;

namespace {

std::size_t pageOffset(const void *p) { return reinterpret_cast<std::uintptr_t>(p) % 4096; }

} // namespace

// The scan's stores must not share their place in a page with the table
// loads that follow them (4K aliasing): the buffers start at fixed offsets,
// however often they grow, and the tables sit at the start of a page.
TEST(ScanBuffers, KeepClearOfTheCompactionTables) {
  ScanBuffers<NeighbourRef> buffers;
  for (std::size_t n : {10, 40, 200, 3000, 50, 70000}) {
    buffers.reserve(n);
    EXPECT_EQ(pageOffset(buffers.rows()), 1024u) << n;
    EXPECT_EQ(pageOffset(buffers.distances()), 2560u) << n;
    EXPECT_GE(reinterpret_cast<const char *>(buffers.distances()),
              reinterpret_cast<const char *>(buffers.rows() + n + scanSlack))
        << "rows and distances overlap for " << n;
    buffers.rows()[n + scanSlack - 1].index = 1; // both hold n + scanSlack
    buffers.distances()[n + scanSlack - 1] = 1.0;
  }
#if WASH_SCAN_AVX2
  EXPECT_EQ(pageOffset(&scanCompaction<2>), 0u);
  EXPECT_EQ(pageOffset(&scanCompaction<3>), 0u);
  EXPECT_LE(sizeof(scanCompaction<2>.wide) + sizeof(scanCompaction<2>.narrow), 1024u);
#endif
}

#if WASH_SCAN_AVX2

namespace {

/// The scalar test's squared distance, written out: (dx*dx + dy*dy) [+ dz*dz].
template <int D, typename T>
double writtenOutSquaredDistance(const wash::Vec<T, D> &q, const wash::Vec<double, D> &c) {
  double d = double(q.at(0)) - c.at(0);
  double d2 = d * d;
  for (int a = 1; a < D; ++a) {
    d = double(q.at(a)) - c.at(a);
    d2 += d * d;
  }
  return d2;
}

/// The scalar test: d2 <= r2.
template <int D, typename T>
std::vector<std::uint64_t> scalarRow(const std::vector<wash::Vec<T, D>> &p,
                                     const wash::Vec<double, D> &c, double r2, Index b, Index e,
                                     Index self) {
  std::vector<std::uint64_t> kept;
  for (Index j = b; j < e; ++j)
    if (j != self && writtenOutSquaredDistance(p[j], c) <= r2)
      kept.push_back(j);
  return kept;
}

/// The AVX2 scan's rows, written as Row (64-bit per-particle lists or 32-bit
/// stored ones); also scanned keeping squared distances, which must be the
/// scalar test's and leave the rows as they were.
template <int D, typename Row, typename T>
std::vector<std::uint64_t> avx2Row(const std::vector<wash::Vec<T, D>> &p,
                                   const wash::Vec<double, D> &c, double r2, Index b, Index e,
                                   Index self) {
  std::vector<Row> out(e - b + scanSlack), again(e - b + scanSlack);
  std::vector<double> d2(e - b + scanSlack);
  const std::size_t kept =
      keepRowAvx2<D, false>(p.data(), p.size(), c, r2, b, e, self, out.data(), nullptr, 0);
  EXPECT_EQ(
      (keepRowAvx2<D, true>(p.data(), p.size(), c, r2, b, e, self, again.data(), d2.data(), 0)),
      kept);
  std::vector<std::uint64_t> rows;
  for (std::size_t k = 0; k < kept; ++k) {
    rows.push_back(out[k].index);
    EXPECT_EQ(again[k].index, out[k].index);
    EXPECT_EQ(d2[k], writtenOutSquaredDistance(p[out[k].index], c)) << "row " << out[k].index;
  }
  return rows;
}

/// Points on a lattice of spacing 0.25 (exact in binary), so that many lie
/// exactly at the radius 0.5 from the centre, which is a lattice point too.
template <int D, typename T = double> std::vector<wash::Vec<T, D>> lattice(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> step(-3, 3);
  std::vector<wash::Vec<T, D>> p(n);
  for (auto &v : p)
    for (int a = 0; a < D; ++a)
      *v[a] = T(0.25 * step(rng));
  return p;
}

/// Every row [b, e) of a small lattice, with the particle itself before, in and
/// after it, on both paths and for both list widths.
template <int D, typename T> void compareRows(unsigned seed) {
  const std::vector<wash::Vec<T, D>> p = lattice<D, T>(seed, 37);
  const Index n = Index(p.size());
  int compared = 0;
  for (Index b = 0; b < n; b += 3)
    for (Index e = b; e <= n; ++e)
      for (Index self : {b, Index(b + 1), Index(b + 2), Index(b + 3), Index(e - 1), n}) {
        const wash::Vec<double, D> c(p[(b * 7 + e) % n]);
        const std::vector<std::uint64_t> expected = scalarRow<D>(p, c, 0.25, b, e, self);
        ASSERT_EQ((avx2Row<D, NeighbourRef>(p, c, 0.25, b, e, self)), expected)
            << "64-bit rows [" << b << ", " << e << "), self " << self;
        ASSERT_EQ((avx2Row<D, StoredNeighbourRef>(p, c, 0.25, b, e, self)), expected)
            << "32-bit rows [" << b << ", " << e << "), self " << self;
        ++compared;
      }
  EXPECT_GT(compared, 1000);
}

} // namespace

TEST(ScanAvx2, KeepsWhatTheScalarScanKeeps) {
  if (!cpuHasAvx2()) { // the dispatch must then keep the scans scalar
    EXPECT_FALSE(avx2Scan());
    return;
  }
  compareRows<2, double>(1);
  compareRows<2, double>(2);
  compareRows<2, float>(5);
  compareRows<3, double>(3);
  compareRows<3, double>(4);
  compareRows<3, float>(6);
}

TEST(ScanAvx2, LatticeHasTiesAtTheRadius) { // the comparisons above test `<=`, not only `<`
  const auto p = lattice<2>(1, 37);
  int ties = 0;
  for (const auto &a : p)
    for (const auto &b : p) {
      const double dx = a.at(0) - b.at(0), dy = a.at(1) - b.at(1);
      ties += dx * dx + dy * dy == 0.25;
    }
  EXPECT_GT(ties, 0);
}

#endif
