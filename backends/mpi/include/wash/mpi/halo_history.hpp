//===- wash/mpi/halo_history.hpp - halo rows kept between searches -*- C++ -*-===//
//
// A halo is rebuilt at every neighbour search, but most of its rows are the
// same particles as before, from the same sender. Such a row is "kept": it
// receives only the columns written since they were last sent (the
// translator's plan, `halo-exchange` in --dump-model), and takes the other
// columns it needs from its previous copy. Every other row is new and
// receives them all. Sender and receiver agree on which rows are kept without
// a message: the sender remembers the ids it sent each rank, the receiver
// the ids it received from each rank, the same lists (docs/backends.md).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

namespace wash::mpi {

using backend::Index;

/// What one halo build leaves for the next.
struct HaloHistory {
  /// By rank: the ids of the rows sent there, sorted.
  std::vector<std::vector<std::uint64_t>> sent;
  /// By rank: the ids of the rows received from there, each with its index
  /// among the stashed rows, sorted by id.
  std::vector<std::vector<std::pair<std::uint64_t, std::size_t>>> received;
  /// The stashed rows' carried columns, one block per column.
  std::vector<char> stash;
  std::size_t stashRows = 0;

  /// No previous build (at the start, or after a search without the split).
  void forget() { *this = HaloHistory(); }

  bool wasSent(int rank, std::uint64_t id) const {
    return std::size_t(rank) < sent.size() &&
           std::binary_search(sent[rank].begin(), sent[rank].end(), id);
  }

  /// The stashed index of the row with `id` received from `rank`, or -1.
  std::int64_t stashed(int rank, std::uint64_t id) const {
    if (std::size_t(rank) >= received.size())
      return -1;
    const auto &list = received[rank];
    auto at = std::lower_bound(list.begin(), list.end(), std::make_pair(id, std::size_t(0)));
    return at != list.end() && at->first == id ? std::int64_t(at->second) : -1;
  }
};

/// Visits the columns `fresh` visits that `kept` does not (by address).
template <typename Kept, typename Fresh> auto carriedColumns(const Kept &kept, const Fresh &fresh) {
  return [kept, fresh](auto f) {
    fresh([&](auto &column) {
      bool inKept = false;
      kept([&](auto &other) {
        inKept = inKept || static_cast<const void *>(&other) == static_cast<const void *>(&column);
      });
      if (!inKept)
        f(column);
    });
  };
}

/// Before the halo is dropped: the ids of the copies received from each rank
/// (positions recv[rank]) and their columns `carried` visits.
template <typename Particles, typename Carried>
void stashHalo(const Particles &P, const std::vector<std::vector<Index>> &recv,
               HaloHistory &history, Carried carried) {
  history.received.assign(recv.size(), {});
  std::vector<Index> rows;
  for (std::size_t r = 0; r < recv.size(); ++r) {
    for (Index q : recv[r]) {
      history.received[r].emplace_back(P.id[q], rows.size());
      rows.push_back(q);
    }
    std::sort(history.received[r].begin(), history.received[r].end());
  }
  history.stash.clear();
  history.stashRows = rows.size();
  carried([&](auto &column) {
    using T = std::remove_cvref_t<decltype(column[0])>;
    const std::size_t start = history.stash.size();
    history.stash.resize(start + rows.size() * sizeof(T));
    for (std::size_t k = 0; k < rows.size(); ++k)
      std::memcpy(history.stash.data() + start + k * sizeof(T), &column[rows[k]], sizeof(T));
  });
}

/// Writes the stashed columns `carried` visits into rows: (position, stashed index).
template <typename Carried>
void restoreStashed(const HaloHistory &history,
                    const std::vector<std::pair<Index, std::size_t>> &rows, Carried carried) {
  std::size_t start = 0;
  carried([&](auto &column) {
    using T = std::remove_cvref_t<decltype(column[0])>;
    for (const auto &[at, k] : rows)
      std::memcpy(&column[at], history.stash.data() + start + k * sizeof(T), sizeof(T));
    start += history.stashRows * sizeof(T);
  });
}

} // namespace wash::mpi
