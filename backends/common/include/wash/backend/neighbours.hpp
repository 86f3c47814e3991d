//===- wash/backend/neighbours.hpp - particle handles and neighbour ranges -*- C++ -*-===//
//
// In generated code a kernel's `wash::Particle&` becomes a Self and its
// `const std::vector<wash::Particle>&` a Neighbours range with the same
// interface (range-for, size(), [k]); field accesses index columns with them.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/cell_grid.hpp>
#include <wash/backend/id_order.hpp>
#include <wash/backend/scan_avx2.hpp>
#include <wash/backend/scan_buffers.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace wash::backend {

/// The particle a kernel runs for.
struct Self {
  Index index;
  constexpr operator Index() const { return index; }
};

/// A neighbour of the particle a force kernel runs for: read-only. Its row is
/// 64-bit in the lists built for one particle at a time (NeighbourRef): g++
/// vectorises gathers of doubles only through 64-bit indices. The lists a
/// NeighbourTable keeps for every particle hold 32-bit rows (StoredNeighbourRef),
/// half the memory.
template <typename Row> struct NeighbourRefOf {
  Row index;
  constexpr operator std::size_t() const { return index; }
};
using NeighbourRef = NeighbourRefOf<std::size_t>;
using StoredNeighbourRef = NeighbourRefOf<Index>;

/// The neighbours of one particle, in canonical order. Built when the kernel
/// starts for that particle by walking the cell grid's candidate ranges and
/// keeping, without branches, the other particles within the radius; the loops
/// of the kernel and its helpers then run over that short list only. The list
/// lives in a per-thread buffer: one Neighbours per thread at a time, which is
/// how the generated drivers use it.
///
/// With Distances (double positions, one-radius search), the scan also keeps
/// each neighbour's distance, which it has all but computed: std::sqrt of the
/// squared distance it tested, summed in component order, so bit for bit what
/// `(n.get_pos() - p.get_pos()).magnitude()` gives. The translator reads it
/// in place of that expression (docs/backends.md).
template <int D, typename PosT, typename Ref = NeighbourRef, bool Distances = false>
class Neighbours {
  static_assert(!Distances || std::is_same_v<PosT, Vec<double, D>>,
                "distances equal the user's only for double positions");

public:
  Neighbours(const CellGrid<D> &grid, const Column<PosT> &pos, Index self) {
    scan(grid, pos, self, grid.radius());
  }

  /// The smoothing-length rule: the other particles within `radius` of
  /// particle `self`, in ascending id order.
  Neighbours(const CellGrid<D> &grid, const Column<PosT> &pos, Index self,
             const Column<std::uint64_t> &ids, double radius) {
    static_assert(!Distances, "the smoothing-length rule reorders the list: no distances");
    scan(grid, pos, self, radius);
    orderById(threadBuffers().rows(), size(), ids);
  }

  /// The symmetric smoothing-length rule: the other particles j within the
  /// pair radius of particle `self`, max(sqrt(selfR2), sqrt(pairR2[j])), in
  /// ascending id order; `pairR2` holds every row's squared support radius and
  /// `reach` bounds the pair radius of every candidate (the grid's candidates
  /// come from it). max(r_i, r_j)^2 is max(r_i^2, r_j^2) exactly: squaring
  /// non-negative numbers, rounded, keeps their order.
  Neighbours(const CellGrid<D> &grid, const Column<PosT> &pos, Index self,
             const Column<std::uint64_t> &ids, double reach, double selfR2, const double *pairR2) {
    static_assert(!Distances, "the smoothing-length rule reorders the list: no distances");
    scan<true>(grid, pos, self, reach, selfR2, pairR2);
    orderById(threadBuffers().rows(), size(), ids);
  }

  /// A list kept elsewhere (NeighbourTable).
  Neighbours(const Ref *begin, const Ref *end) : begin_(begin), end_(end) {
    static_assert(!Distances, "stored lists keep no distances");
  }

  /// The same lists with only the neighbours of particle type `t` (a force
  /// kernel's neighbour type), in the same order: filtered as the list is
  /// built, so the kernel's loops see only those.
  Neighbours(const CellGrid<D> &grid, const Column<PosT> &pos, Index self,
             const Column<std::uint32_t> &type, std::uint32_t t) {
    scan(grid, pos, self, grid.radius());
    keepType(type, t);
  }
  Neighbours(const CellGrid<D> &grid, const Column<PosT> &pos, Index self,
             const Column<std::uint64_t> &ids, double radius, const Column<std::uint32_t> &type,
             std::uint32_t t)
      : Neighbours(grid, pos, self, ids, radius) {
    keepType(type, t);
  }
  Neighbours(const Ref *begin, const Ref *end, const Column<std::uint32_t> &type, std::uint32_t t)
      : begin_(begin), end_(end) {
    static_assert(!Distances, "stored lists keep no distances");
    keepType(type, t);
  }

  const Ref *begin() const { return begin_; }
  const Ref *end() const { return end_; }
  std::size_t size() const { return std::size_t(end_ - begin_); }
  bool empty() const { return begin_ == end_; }
  const Ref &operator[](std::size_t k) const { return begin_[k]; }
  const Ref &at(std::size_t k) const {
    if (k >= size())
      throw std::out_of_range("wash: neighbour index out of range");
    return begin_[k];
  }
  /// The distance from the particle to neighbour n, an element of this list
  /// (the range-for variable or a reference to [k], never a copy).
  double distance(const Ref &n) const {
    static_assert(Distances, "this list keeps no distances");
    return dist_[&n - begin_];
  }
  const Ref &front() const { return *begin_; }
  const Ref &back() const { return end_[-1]; }
  const Ref *cbegin() const { return begin_; }
  const Ref *cend() const { return end_; }

private:
  /// Keeps the entries whose particle is of type t, in order, in the
  /// per-thread buffer (in place when the list is already there), branch-free.
  void keepType(const Column<std::uint32_t> &type, std::uint32_t t) {
    ScanBuffers<Ref> &buffers = threadBuffers();
    const std::size_t n = size();
    if (begin_ != buffers.rows())
      buffers.reserve(n); // a stored list: copied out of the table
    Ref *out = buffers.rows();
    const Ref *in = begin_;
    double *dist = nullptr;
    if constexpr (Distances)
      dist = buffers.distances(); // the scan's, aligned with the rows
    std::size_t kept = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Ref r = in[k];
      out[kept] = r;
      if constexpr (Distances)
        dist[kept] = dist[k];
      kept += type[r.index] == t;
    }
    begin_ = out;
    end_ = out + kept;
    if constexpr (Distances)
      dist_ = dist;
  }

  /// Fills the per-thread buffer with the other particles within `radius` of
  /// particle `self`, in the grid's candidate order, without branches: every
  /// candidate is written and kept (the count advanced) if it passes. With
  /// Pairwise, the candidates come from `radius` but candidate j passes
  /// within max(r2, pairR2[j]) (squared).
  template <bool Pairwise = false>
  void scan(const CellGrid<D> &grid, const Column<PosT> &pos, Index self, double radius,
            double pairSelfR2 = 0.0, const double *pairR2 = nullptr) {
    const Vec<double, D> centre(pos[self]);
    const double r2 = Pairwise ? pairSelfR2 : radius * radius;
    CandidateRanges ranges;
    grid.candidates(centre, radius, ranges);
    ScanBuffers<Ref> &buffers = threadBuffers();
    buffers.reserve(ranges.total);
    Ref *out = buffers.rows();
    double *dist = nullptr; // squared distances, then distances
    if constexpr (Distances)
      dist_ = dist = buffers.distances();
    std::size_t kept = 0;
    const PosT *p = pos.data();
#if WASH_SCAN_AVX2
    if constexpr (std::is_same_v<PosT, Vec<double, D>> || std::is_same_v<PosT, Vec<float, D>>)
      if (avx2Scan()) { // four candidates at a time; it skips `self` itself
        kept = keepRangesAvx2<D, Distances, Pairwise>(p, pos.size(), centre, r2, ranges, self, out,
                                                      dist, pairR2);
        begin_ = out;
        end_ = out + kept;
        return;
      }
#endif
    for (int r = 0; r < ranges.count; ++r) {
      const Index b = ranges.begin[r], e = ranges.end[r];
      if constexpr (Pairwise) {
        if (b <= self && self < e) {
          kept = keepPairs(p, centre, r2, pairR2, b, self, out, kept);
          kept = keepPairs(p, centre, r2, pairR2, self + 1, e, out, kept);
        } else {
          kept = keepPairs(p, centre, r2, pairR2, b, e, out, kept);
        }
      } else if (b <= self && self < e) { // skip the particle itself by splitting its row
        kept = keep(p, centre, r2, b, self, out, dist, kept);
        kept = keep(p, centre, r2, self + 1, e, out, dist, kept);
      } else {
        kept = keep(p, centre, r2, b, e, out, dist, kept);
      }
    }
    if constexpr (Distances)
      for (std::size_t k = 0; k < kept; ++k)
        dist[k] = std::sqrt(dist[k]);
    begin_ = out;
    end_ = out + kept;
  }

  /// Appends the candidates [b, e) within sqrt(r2) of centre to out[kept..]
  /// (and with Distances their squared distances to d2out[kept..]).
  static std::size_t keep(const PosT *__restrict p, const Vec<double, D> &centre, double r2,
                          Index b, Index e, Ref *__restrict out, double *__restrict d2out,
                          std::size_t kept) {
#if defined(__GNUC__) // g++ and clang: vector extensions
    if constexpr (D == 2 && std::is_same_v<PosT, Vec<double, 2>>)
      return keepPlanar(p, centre, r2, b, e, out, d2out, kept);
#endif
    for (Index j = b; j < e; ++j) {
      const double d2 = squaredDistance(p[j], centre);
      out[kept].index = j;
      if constexpr (Distances)
        d2out[kept] = d2;
      kept += d2 <= r2;
    }
    return kept;
  }

  /// keep() with a radius per pair: candidate j passes within
  /// max(r2, pairR2[j]).
  static std::size_t keepPairs(const PosT *__restrict p, const Vec<double, D> &centre, double r2,
                               const double *__restrict pairR2, Index b, Index e,
                               Ref *__restrict out, std::size_t kept) {
    for (Index j = b; j < e; ++j) {
      const double d2 = squaredDistance(p[j], centre);
      out[kept].index = j;
      kept += d2 <= std::max(r2, pairR2[j]);
    }
    return kept;
  }

#if defined(__GNUC__)
  /// keep() for 2D double positions, both coordinates in one SSE2 register:
  /// the same arithmetic lane by lane (dx*dx + dy*dy), in a shorter loop. The
  /// scalar loop's speed depends on where the compiler happens to place it
  /// (the seed program varied by 6 % with unrelated changes elsewhere in the
  /// file); this one's did not (docs/performance.md).
  static std::size_t keepPlanar(const Vec<double, 2> *__restrict p, const Vec<double, 2> &centre,
                                double r2, Index b, Index e, Ref *__restrict out,
                                double *__restrict d2out, std::size_t kept) {
    typedef double Pair __attribute__((vector_size(16)));
    static_assert(sizeof(Vec<double, 2>) == sizeof(Pair) &&
                      std::is_trivially_copyable_v<Vec<double, 2>>,
                  "Vec<double, 2> is two doubles");
    const Pair c = {centre.at(0), centre.at(1)};
    for (Index j = b; j < e; ++j) {
      Pair d;
      std::memcpy(&d, &p[j], sizeof d);
      d -= c;
      d *= d;
      const double d2 = d[0] + d[1];
      out[kept].index = j;
      if constexpr (Distances)
        d2out[kept] = d2;
      kept += d2 <= r2;
    }
    return kept;
  }
#endif

  /// Puts the n rows at `rows`, as the scan left them (ascending), in
  /// ascending (id, row) order: the order of the `id << 32 | row` keys, which
  /// sortByIdRadix gives as it keeps the rows' order among equal ids, and
  /// orderByIdBitmap faster when the ids are distinct and close together. Not
  /// inlined, so that profiles show what it costs.
  [[gnu::noinline]] static void orderById(Ref *rows, std::size_t n,
                                          const Column<std::uint64_t> &ids) {
    if (n < 2)
      return;
    std::uint64_t lo = ids[rows[0].index], hi = lo; // ids below 2^32
    for (std::size_t k = 1; k < n; ++k) {
      lo = std::min(lo, ids[rows[k].index]);
      hi = std::max(hi, ids[rows[k].index]);
    }
    thread_local IdBitmap bitmap;
    if (orderByIdBitmap(
            rows, n, std::uint32_t(lo), std::uint32_t(hi),
            [&](std::size_t row) { return ids[row]; }, bitmap))
      return;
    std::vector<std::uint64_t> &keys = threadKeys();
    if (keys.size() < 2 * n)
      keys.resize(2 * n);
    for (std::size_t k = 0; k < n; ++k) // ids and rows below 2^32
      keys[k] = ids[rows[k].index] << 32 | rows[k].index;
    const std::uint64_t *sorted = sortByIdRadix(keys.data(), keys.data() + n, n);
    for (std::size_t k = 0; k < n; ++k)
      rows[k].index = Index(sorted[k] & 0xffffffffu);
  }

  static ScanBuffers<Ref> &threadBuffers() {
    thread_local ScanBuffers<Ref> buffers;
    return buffers;
  }
  /// Keys, and the radix passes' scratch space.
  static std::vector<std::uint64_t> &threadKeys() {
    thread_local std::vector<std::uint64_t> keys;
    return keys;
  }

  const Ref *begin_;
  const Ref *end_;
  const double *dist_ = nullptr; // with Distances: dist_[k] for begin_[k]
};

} // namespace wash::backend
