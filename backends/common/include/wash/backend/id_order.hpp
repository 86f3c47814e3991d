//===- wash/backend/id_order.hpp - a neighbour list put in id order -*- C++ -*-===//
//
// Under the smoothing-length rule a list is kept in ascending id order. The
// ids of one particle's neighbours lie close together (a neighbourhood is
// created together), so their offsets from the smallest fit in a few bits:
// two radix passes of 8 bits at most for 65536 ids, three for 2^24. That is
// a few branch-free passes over the list, where std::sort of the same keys,
// and as well a merge of the ascending runs the cell order leaves (one or
// two neighbours a cell), cost as much as the scan that found them
// (docs/performance.md).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

namespace wash::backend {

/// Sorts the n entries at `keys`, each `id << 32 | row` with ids and rows
/// below 2^32, by id, keeping the given order among equal ids (an LSD radix
/// sort is stable); `scratch` has room for n entries. Returns where the
/// sorted entries are: keys or scratch (the passes go back and forth).
inline std::uint64_t *sortByIdRadix(std::uint64_t *keys, std::uint64_t *scratch, std::size_t n) {
  if (n < 2)
    return keys;
  std::uint32_t lo = std::uint32_t(keys[0] >> 32), hi = lo;
  for (std::size_t k = 1; k < n; ++k) {
    const std::uint32_t id = std::uint32_t(keys[k] >> 32);
    lo = std::min(lo, id);
    hi = std::max(hi, id);
  }
  // The ids' offsets from lo take `bits` bits: that many, in the fewest
  // passes of at most 8 bits, of equal widths.
  const int bits = std::bit_width(hi - lo);
  const int passes = (bits + 7) / 8;
  if (passes == 0)
    return keys; // one id
  const int width = (bits + passes - 1) / passes;
  const std::uint32_t buckets = 1u << width, mask = buckets - 1;
  std::uint32_t start[256];
  std::uint64_t *from = keys, *to = scratch;
  for (int pass = 0; pass < passes; ++pass) {
    const int shift = pass * width;
    const auto digit = [&](std::uint64_t key) {
      return ((std::uint32_t(key >> 32) - lo) >> shift) & mask;
    };
    std::memset(start, 0, buckets * sizeof start[0]);
    for (std::size_t k = 0; k < n; ++k)
      ++start[digit(from[k])];
    std::uint32_t sum = 0;
    for (std::uint32_t b = 0; b < buckets; ++b)
      sum += std::exchange(start[b], sum);
    for (std::size_t k = 0; k < n; ++k)
      to[start[digit(from[k])]++] = from[k];
    std::swap(from, to);
  }
  return from;
}

/// Where orderByIdBitmap keeps its bits and rows: one per thread. The bits
/// are all clear between uses.
struct IdBitmap {
  static constexpr std::uint32_t span = 1u << 16; ///< ids within span of the smallest
  std::vector<std::uint64_t> bits = std::vector<std::uint64_t>(span / 64, 0);
  std::vector<std::uint32_t> rows = std::vector<std::uint32_t>(span);
};

/// The common case without sorting: the n entries at `list` (each with a row
/// `.index`), whose ids `idOf(row)` lie in [lo, hi], put in ascending id order
/// when those ids are distinct and hi - lo < IdBitmap::span. Each id sets its
/// bit in a bitmap of the span and leaves its row at its offset; the set bits,
/// read out a 64-bit word at a time, give the rows in id order: n writes and
/// (hi - lo) / 64 words, where a radix sort makes two or three passes over
/// the list and its bucket tables (docs/performance.md). Returns false, the
/// list unchanged, when the span is larger or two ids are equal (a periodic
/// image and its particle; the radix sort orders those by row).
template <typename Entry, typename IdOf>
bool orderByIdBitmap(Entry *list, std::size_t n, std::uint32_t lo, std::uint32_t hi, IdOf idOf,
                     IdBitmap &m) {
  if (hi - lo >= IdBitmap::span)
    return false;
  std::uint64_t *bits = m.bits.data();
  std::uint32_t *rows = m.rows.data();
  std::uint64_t clash = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t offset = std::uint32_t(idOf(list[k].index)) - lo;
    const std::uint64_t bit = std::uint64_t(1) << (offset & 63);
    clash |= bits[offset >> 6] & bit;
    bits[offset >> 6] |= bit;
    rows[offset] = std::uint32_t(list[k].index);
  }
  const std::size_t words = ((hi - lo) >> 6) + 1;
  if (clash) {
    std::memset(bits, 0, words * sizeof bits[0]);
    return false;
  }
  std::size_t out = 0;
  for (std::size_t w = 0; w < words; ++w) {
    std::uint64_t word = bits[w];
    bits[w] = 0;
    for (; word; word &= word - 1)
      list[out++].index = rows[w * 64 + std::size_t(std::countr_zero(word))];
  }
  return true;
}

} // namespace wash::backend
