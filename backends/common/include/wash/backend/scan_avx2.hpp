//===- wash/backend/scan_avx2.hpp - the neighbour test, four at a time -*- C++ -*-===//
//
// Programs are built for the baseline x86-64 instruction set (SSE2), so that
// they run on any x86-64 machine; on one with AVX2, the neighbour scan (2D and
// 3D, double or float positions), the hottest loop of a search, takes this path
// instead, chosen at run time. It computes the same squared distances
// ((dx*dx + dy*dy) + dz*dz, lane by lane) and keeps the same candidates in the
// same order, so results do not depend on the machine
// (test/backends/scan_avx2_test.cpp compares it with the scalar test).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/cell_grid.hpp>
#include <wash/backend/columns.hpp>
#include <wash/backend/scan_buffers.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <type_traits>

#if defined(__GNUC__) && defined(__x86_64__)
#define WASH_SCAN_AVX2 1
#include <immintrin.h>
#else
#define WASH_SCAN_AVX2 0
#endif

namespace wash::backend {

/// The squared distance every path of the neighbour test computes, in double:
/// (dx*dx + dy*dy) [+ dz*dz]; the reference starts from 0 + dx*dx, the same
/// number (dx*dx is never -0).
template <int D, typename T>
inline double squaredDistance(const Vec<T, D> &q, const Vec<double, D> &centre) {
  double d = double(q.at(0)) - centre.at(0);
  double d2 = d * d;
  for (int a = 1; a < D; ++a) {
    d = double(q.at(a)) - centre.at(a);
    d2 += d * d;
  }
  return d2;
}

#if WASH_SCAN_AVX2

/// Whether this machine runs AVX2 code.
inline bool cpuHasAvx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}

/// Whether scans take the AVX2 path: on a machine that has it, unless the
/// environment sets WASH_SCALAR_SCAN (to check that results do not depend on
/// the path; tests also switch it here). Decided once.
inline bool &avx2Scan() {
  static bool use = cpuHasAvx2() && !std::getenv("WASH_SCALAR_SCAN");
  return use;
}

/// The candidate each lane of a block's squared distances holds: 2D
/// coordinates come out of their unpacking as 0 2 1 3, and the tables below
/// follow that order instead of a shuffle putting the lanes back.
template <int D> inline constexpr int laneCandidate[4] = {0, 1, 2, 3};
template <> inline constexpr int laneCandidate<2>[4] = {0, 2, 1, 3};

/// For each 4-bit mask of kept lanes, the 32-bit lanes that move their rows
/// (64-bit lanes of a register) to the front in candidate order: whole rows
/// for 64-bit lists, their low halves for 32-bit ones. Page-aligned, so the
/// tables take the page offsets below scanTableBytes, which the scan's
/// buffers keep clear of (scan_buffers.hpp).
template <int D> struct alignas(4096) ScanCompaction {
  alignas(32) std::int32_t wide[16][8];
  alignas(32) std::int32_t narrow[16][8];
  constexpr ScanCompaction() : wide{}, narrow{} {
    for (int mask = 0; mask < 16; ++mask) {
      int to = 0;
      for (int candidate = 0; candidate < 4; ++candidate) {
        int lane = 0;
        while (laneCandidate<D>[lane] != candidate)
          ++lane;
        if (mask >> lane & 1) {
          wide[mask][2 * to] = 2 * lane;
          wide[mask][2 * to + 1] = 2 * lane + 1;
          narrow[mask][to] = 2 * lane;
          ++to;
        }
      }
    }
  }
};
template <int D> inline constexpr ScanCompaction<D> scanCompaction{};
static_assert(sizeof(ScanCompaction<2>::wide) + sizeof(ScanCompaction<2>::narrow) <= scanTableBytes,
              "the compaction tables fit the page offsets the scan buffers leave them");

/// Stores the rows of `rows` (four 64-bit lanes) that `mask` keeps at `to`, in
/// candidate order, as Ref; writes a whole block of four Refs.
template <int D, typename Ref>
__attribute__((target("avx2"))) inline void storeKept(Ref *to, __m256i rows, int mask) {
  static_assert((sizeof(Ref) == 8 || sizeof(Ref) == 4) && std::is_trivially_copyable_v<Ref>,
                "32- or 64-bit rows");
  if constexpr (sizeof(Ref) == 8) {
    const __m256i order =
        _mm256_load_si256(reinterpret_cast<const __m256i *>(scanCompaction<D>.wide[mask]));
    _mm256_storeu_si256(reinterpret_cast<__m256i *>(to), _mm256_permutevar8x32_epi32(rows, order));
  } else {
    const __m256i order =
        _mm256_load_si256(reinterpret_cast<const __m256i *>(scanCompaction<D>.narrow[mask]));
    _mm_storeu_si128(reinterpret_cast<__m128i *>(to),
                     _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(rows, order)));
  }
}

/// The candidates of one block of four (rows, their squared distances d2, lane
/// by lane in laneCandidate<D> order) that pass the test, less the particle
/// itself and the rows at or past `end`, stored at out[kept..], and with
/// Distances their squared distances at d2out[kept..]; the new count.
template <int D, bool Distances, typename Ref>
__attribute__((target("avx2"))) inline std::size_t
keepBlock(Ref *out, double *d2out, std::size_t kept, __m256d d2, __m256d limit, __m256i rows,
          __m256i itself, __m256i end) {
  const __m256i near = _mm256_castpd_si256(_mm256_cmp_pd(d2, limit, _CMP_LE_OQ));
  const __m256i inRow = _mm256_cmpgt_epi64(end, rows);
  const __m256i kept4 =
      _mm256_andnot_si256(_mm256_cmpeq_epi64(rows, itself), _mm256_and_si256(near, inRow));
  const int mask = _mm256_movemask_pd(_mm256_castsi256_pd(kept4));
  storeKept<D>(out + kept, rows, mask);
  if constexpr (Distances) // the same lanes: 64-bit, like wide rows
    storeKept<D>(reinterpret_cast<std::uint64_t *>(d2out + kept), _mm256_castpd_si256(d2), mask);
  return kept + std::size_t(__builtin_popcount(unsigned(mask)));
}

/// The coordinates of four candidates from p[j] on, as stored (x0 y0 x1 y1 |
/// x2 y2 x3 y3 in 2D; x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3 in 3D), in
/// double: float positions are converted (exactly), as the scalar scan does.
template <int D> struct Block {
  __m256d part[D];
};
template <int D, typename T>
__attribute__((target("avx2"))) inline Block<D> loadBlock(const Vec<T, D> *p, Index j) {
  static_assert(sizeof(Vec<T, D>) == sizeof(T) * D, "Vec<T, D> is D numbers");
  const T *at = reinterpret_cast<const T *>(p + j);
  Block<D> block;
  for (int k = 0; k < D; ++k) {
    if constexpr (std::is_same_v<T, double>)
      block.part[k] = _mm256_loadu_pd(at + 4 * k);
    else
      block.part[k] = _mm256_cvtps_pd(_mm_loadu_ps(at + 4 * k));
  }
  return block;
}

/// The four squared distances from centre, dx*dx + dy*dy lane by lane: the
/// x and the y of the four unpacked from the (x, y) pairs, which leaves them
/// in laneCandidate<2> order (d0 d2 d1 d3).
__attribute__((target("avx2"))) inline __m256d blockDistances(const Block<2> &block,
                                                              const Vec<double, 2> &centre) {
  const __m256d x = _mm256_unpacklo_pd(block.part[0], block.part[1]); // x0 x2 x1 x3
  const __m256d y = _mm256_unpackhi_pd(block.part[0], block.part[1]); // y0 y2 y1 y3
  const __m256d dx = _mm256_sub_pd(x, _mm256_set1_pd(centre.at(0)));
  const __m256d dy = _mm256_sub_pd(y, _mm256_set1_pd(centre.at(1)));
  return _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
}

/// The same in 3D, (dx*dx + dy*dy) + dz*dz, the coordinates regrouped by
/// axis first.
__attribute__((target("avx2"))) inline __m256d blockDistances(const Block<3> &block,
                                                              const Vec<double, 3> &centre) {
  const __m256d a = block.part[0], m = block.part[1], c = block.part[2];
  // x: a0 a3 m2 c1; y: a1 m0 m3 c2; z: a2 m1 c0 c3. A shuffle takes its low
  // pair from the low halves of its sources and its high pair from the high
  // halves, so each axis is a blend of two shuffles.
  const __m256d am = _mm256_permute2f128_pd(a, m, 0x21); // a2 a3 m0 m1
  const __m256d mc = _mm256_permute2f128_pd(m, c, 0x21); // m2 m3 c0 c1
  const __m256d x =
      _mm256_blend_pd(_mm256_shuffle_pd(a, am, 0x2), _mm256_shuffle_pd(m, mc, 0x8), 0xC);
  const __m256d y =
      _mm256_blend_pd(_mm256_shuffle_pd(a, m, 0x1), _mm256_shuffle_pd(m, c, 0x4), 0xC);
  const __m256d z =
      _mm256_blend_pd(_mm256_shuffle_pd(am, m, 0x2), _mm256_shuffle_pd(mc, c, 0x8), 0xC);
  const __m256d dx = _mm256_sub_pd(x, _mm256_set1_pd(centre.at(0)));
  const __m256d dy = _mm256_sub_pd(y, _mm256_set1_pd(centre.at(1)));
  const __m256d dz = _mm256_sub_pd(z, _mm256_set1_pd(centre.at(2)));
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)),
                       _mm256_mul_pd(dz, dz));
}

/// Appends the candidates [b, e) other than `self` within sqrt(r2) of centre
/// to out[kept..], four candidates an iteration: their squared distances in
/// one AVX2 register, the test's outcomes (within the radius, before e, not
/// `self`) as one mask, the kept rows moved to the front of a block by a table
/// and stored whole (hence scanSlack). A row's
/// last block reads up to three positions past e, so `count`, the column's
/// size, bounds the blocks; the few candidates that remain are tested one at a
/// time. With Distances, the squared distances kept go to d2out[kept..] too.
/// With Pairwise, candidate j passes within max(r2, pairR2[j]) (squared),
/// pairR2 having an entry for each of the `count` rows.
template <int D, bool Distances, bool Pairwise = false, typename T, typename Ref>
__attribute__((target("avx2"))) inline std::size_t
keepRowAvx2(const Vec<T, D> *__restrict p, std::size_t count, const Vec<double, D> &centre,
            double r2, Index b, Index e, Index self, Ref *__restrict out, double *__restrict d2out,
            std::size_t kept, const double *__restrict pairR2 = nullptr) {
  const __m256d limit = _mm256_set1_pd(r2);
  const __m256i itself = _mm256_set1_epi64x(std::int64_t(self));
  const __m256i end = _mm256_set1_epi64x(std::int64_t(e));
  const __m256i four = _mm256_set1_epi64x(4);
  constexpr const int *lane = laneCandidate<D>;
  __m256i rows = _mm256_add_epi64(_mm256_set1_epi64x(std::int64_t(b)),
                                  _mm256_setr_epi64x(lane[0], lane[1], lane[2], lane[3]));
  Index j = b;
  for (; j < e && std::size_t(j) + 4 <= count; j += 4, rows = _mm256_add_epi64(rows, four)) {
    __m256d blockLimit = limit;
    if constexpr (Pairwise) { // the four candidates' radii, in lane order
      __m256d pair = _mm256_loadu_pd(pairR2 + j);
      if constexpr (D == 2)
        pair = _mm256_permute4x64_pd(pair, 0xD8); // 0 2 1 3
      blockLimit = _mm256_max_pd(limit, pair);
    }
    kept = keepBlock<D, Distances>(out, d2out, kept, blockDistances(loadBlock(p, j), centre),
                                   blockLimit, rows, itself, end);
  }
  for (; j < e; ++j) { // at the column's end: the same test, one at a time
    const double d2 = squaredDistance(p[j], centre);
    out[kept].index = j;
    if constexpr (Distances)
      d2out[kept] = d2;
    double limitJ = r2;
    if constexpr (Pairwise)
      limitJ = std::max(r2, pairR2[j]);
    kept += (d2 <= limitJ) & (j != self);
  }
  return kept;
}

/// Every candidate range of one particle through keepRowAvx2 (one call per
/// particle: the constants are set up once, not per row); the count kept.
/// With Distances, dist[k] is the distance to the k-th neighbour kept:
/// std::sqrt of its squared distance, four at a time (whole blocks, hence
/// scanSlack).
template <int D, bool Distances, bool Pairwise = false, typename T, typename Ref>
__attribute__((target("avx2"))) std::size_t
keepRangesAvx2(const Vec<T, D> *__restrict p, std::size_t count, const Vec<double, D> &centre,
               double r2, const CandidateRanges &ranges, Index self, Ref *__restrict out,
               double *__restrict dist, const double *__restrict pairR2 = nullptr) {
  std::size_t kept = 0;
  for (int r = 0; r < ranges.count; ++r)
    kept = keepRowAvx2<D, Distances, Pairwise>(p, count, centre, r2, ranges.begin[r],
                                               ranges.end[r], self, out, dist, kept, pairR2);
  if constexpr (Distances)
    for (std::size_t k = 0; k < kept; k += 4)
      _mm256_storeu_pd(dist + k, _mm256_sqrt_pd(_mm256_loadu_pd(dist + k)));
  return kept;
}

#endif

} // namespace wash::backend
