// sortByIdRadix must order `id << 32 | row` keys as std::sort does, given
// rows in ascending order (as a scan leaves them): whatever the number of
// keys and however far apart the ids, from one id to the whole 32 bits; and
// orderByIdBitmap must give the same order for distinct ids close together.
#include <wash/backend/id_order.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <random>
#include <vector>

using wash::backend::sortByIdRadix;

namespace {

std::vector<std::uint64_t> sortedByRadix(std::vector<std::uint64_t> keys) {
  std::vector<std::uint64_t> scratch(keys.size());
  const std::uint64_t *sorted = sortByIdRadix(keys.data(), scratch.data(), keys.size());
  return std::vector<std::uint64_t>(sorted, sorted + keys.size());
}

std::vector<std::uint64_t> sortedByStd(std::vector<std::uint64_t> keys) {
  std::sort(keys.begin(), keys.end());
  return keys;
}

/// n keys with ascending rows (from `row`) and ids drawn from
/// [base, base + span].
std::vector<std::uint64_t> keysWithin(std::size_t n, std::uint64_t base, std::uint64_t span,
                                      std::uint32_t row, std::mt19937_64 &rng) {
  std::uniform_int_distribution<std::uint64_t> id(base, base + span);
  std::vector<std::uint64_t> keys(n);
  for (std::size_t k = 0; k < n; ++k)
    keys[k] = id(rng) << 32 | (row + k);
  return keys;
}

} // namespace

TEST(IdOrder, EmptyAndSingleKeyLists) {
  EXPECT_TRUE(sortedByRadix({}).empty());
  EXPECT_EQ(sortedByRadix({42}), std::vector<std::uint64_t>{42});
}

TEST(IdOrder, EqualIdsKeepTheirRowOrder) {
  std::vector<std::uint64_t> keys{7ull << 32 | 1, 7ull << 32 | 2, 3ull << 32 | 3, 7ull << 32 | 4};
  EXPECT_EQ(sortedByRadix(keys), sortedByStd(keys));
  std::vector<std::uint64_t> same{5ull << 32 | 0, 5ull << 32 | 9};
  EXPECT_EQ(sortedByRadix(same), same);
}

TEST(IdOrder, ExtremeIdsAndRows) {
  std::vector<std::uint64_t> keys{0xffffffffull << 32 | 0, 0ull << 32 | 1, 0x80000000ull << 32 | 2,
                                  0xfffffffeull << 32 | 0xffffffffu};
  EXPECT_EQ(sortedByRadix(keys), sortedByStd(keys));
}

TEST(IdOrder, MatchesStdSortForEverySpanOfIds) {
  std::mt19937_64 rng(2026);
  // Spans from one bit to 32, around each pass-count boundary; bases near 0
  // and near 2^32 - span.
  for (std::uint64_t span : {1ull, 2ull, 255ull, 256ull, 1000ull, 65535ull, 65536ull, 70000ull,
                             (1ull << 24) - 1, 1ull << 24, 1ull << 31, 0xffffffffull})
    for (std::size_t n : {2u, 3u, 17u, 146u, 1000u})
      for (std::uint64_t base : {0ull, 12345ull, 0xffffffffull - span}) {
        std::vector<std::uint64_t> keys = keysWithin(n, base, span, 100, rng);
        EXPECT_EQ(sortedByRadix(keys), sortedByStd(keys))
            << n << " keys, ids in [" << base << ", " << base + span << "]";
      }
}

namespace {

struct Entry {
  std::size_t index;
};

/// orderByIdBitmap on rows 0..n-1 with ids `ids`: the rows in id order, or
/// nothing if it declined.
std::optional<std::vector<std::size_t>> bitmapOrder(const std::vector<std::uint64_t> &ids,
                                                    wash::backend::IdBitmap &bitmap) {
  std::vector<Entry> list(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k)
    list[k].index = k;
  const auto [lo, hi] = std::minmax_element(ids.begin(), ids.end());
  if (!wash::backend::orderByIdBitmap(
          list.data(), list.size(), std::uint32_t(*lo), std::uint32_t(*hi),
          [&](std::size_t row) { return ids[row]; }, bitmap)) {
    for (std::size_t k = 0; k < list.size(); ++k)
      EXPECT_EQ(list[k].index, k) << "a declined list must stay as it was";
    return std::nullopt;
  }
  std::vector<std::size_t> rows;
  for (const Entry &e : list)
    rows.push_back(e.index);
  return rows;
}

/// The rows 0..n-1 in the order of their `id << 32 | row` keys.
std::vector<std::size_t> keyOrder(const std::vector<std::uint64_t> &ids) {
  std::vector<std::uint64_t> keys;
  for (std::size_t k = 0; k < ids.size(); ++k)
    keys.push_back(ids[k] << 32 | k);
  std::sort(keys.begin(), keys.end());
  std::vector<std::size_t> rows;
  for (std::uint64_t key : keys)
    rows.push_back(std::size_t(key & 0xffffffffu));
  return rows;
}

} // namespace

TEST(IdOrder, BitmapOrdersDistinctCloseIdsAsTheKeysDo) {
  std::mt19937_64 rng(22);
  wash::backend::IdBitmap bitmap; // reused: each use must leave it clear
  for (std::uint64_t span : {1ull, 63ull, 64ull, 65ull, 1000ull, 65535ull})
    for (std::size_t n : {2u, 3u, 17u, 80u, 146u})
      for (std::uint64_t base : {0ull, 12345ull, 0xffffffffull - span}) {
        if (n > span + 1)
          continue;
        // n distinct ids from [base, base + span], both ends among them.
        std::vector<std::uint64_t> ids{base, base + span};
        std::uniform_int_distribution<std::uint64_t> id(base, base + span);
        while (ids.size() < n)
          if (std::uint64_t v = id(rng); std::find(ids.begin(), ids.end(), v) == ids.end())
            ids.push_back(v);
        std::shuffle(ids.begin(), ids.end(), rng);
        EXPECT_EQ(bitmapOrder(ids, bitmap), keyOrder(ids))
            << n << " ids in [" << base << ", " << base + span << "]";
      }
}

TEST(IdOrder, BitmapDeclinesEqualIdsAndWideSpans) {
  wash::backend::IdBitmap bitmap;
  EXPECT_EQ(bitmapOrder({7, 3, 7, 5}, bitmap), std::nullopt);         // an id twice
  EXPECT_EQ(bitmapOrder({0, 65536, 3}, bitmap), std::nullopt);        // span 2^16
  EXPECT_EQ(bitmapOrder({9, 2, 70, 4}, bitmap), (std::vector<std::size_t>{1, 3, 0, 2})); // clear after
}
