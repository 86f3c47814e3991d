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

} // namespace wash::backend
