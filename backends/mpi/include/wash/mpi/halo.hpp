//===- wash/mpi/halo.hpp - migration, halo build and halo exchange -*- C++ -*-===//
//
// A rank stores its own particles and, while a neighbour search lasts, halo
// copies of other ranks' particles that lie within the influence radius of one
// of its cells. Owned and halo particles share the columns (the cell sort mixes
// them, cells being whole); HaloPlan remembers which positions are owned, which
// to send to whom, and where each received copy lives.
//
// The column-generic functions take a `Particles` with forEachColumn(f), and a
// `Fields` callable that calls its argument on each column to transfer.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/backend/periodic.hpp>
#include <wash/mpi/comm.hpp>
#include <wash/mpi/domain.hpp>
#include <wash/mpi/for_each.hpp>
#include <wash/mpi/halo_history.hpp>
#include <wash/mpi/pair_reach.hpp>
#include <wash/detail/run_output.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <vector>

namespace wash::mpi {

using backend::Index;

/// The owned particles and local periodic images (backend::Images), plus the
/// copies exchanged with other ranks.
struct HaloPlan : backend::Images {
  std::vector<std::vector<Index>> send, recv; ///< by rank: positions sent / received there
  std::size_t ghosts = 0;                     ///< copies of other ranks' particles

  /// No halo and no images: positions 0..n-1 are all owned.
  void ownAll(std::size_t n) {
    Images::ownAll(n);
    ghosts = 0;
    send.assign(ranks(), {});
    recv.assign(ranks(), {});
  }

  /// After columns were reordered (new[k] = old[order[k]]): follow the positions.
  void permuted(const std::vector<Index> &order) {
    const std::vector<Index> where = inverse(order);
    moved(where);
    for (auto *lists : {&send, &recv})
      for (auto &list : *lists)
        for (Index &p : list)
          p = where[p];
  }
};

namespace detail {

template <typename T> void pack(const backend::Column<T> &c, const std::vector<Index> &at,
                                std::vector<char> &out) {
  std::size_t start = out.size();
  out.resize(start + at.size() * sizeof(T));
  for (std::size_t k = 0; k < at.size(); ++k)
    std::memcpy(out.data() + start + k * sizeof(T), &c[at[k]], sizeof(T));
}

template <typename T>
const char *unpack(backend::Column<T> &c, const std::vector<Index> &at, const char *in) {
  for (std::size_t k = 0; k < at.size(); ++k)
    std::memcpy(&c[at[k]], in + k * sizeof(T), sizeof(T));
  return in + at.size() * sizeof(T);
}

/// Sends the columns `fields` visits, at send[r], to each rank r, and writes
/// what arrives from rank r at recv[r]. One message per rank pair.
template <typename Fields>
void transfer(const std::vector<std::vector<Index>> &send,
              const std::vector<std::vector<Index>> &recv, Fields fields, std::uint64_t &counter) {
  const int n = ranks();
  std::size_t rowBytes = 0;
  fields([&](auto &column) { rowBytes += sizeof(column[0]); });
  std::vector<char> out;
  std::vector<std::size_t> outBytes(n), inBytes(n);
  for (int r = 0; r < n; ++r) {
    fields([&](auto &column) { pack(column, send[r], out); });
    outBytes[r] = send[r].size() * rowBytes;
    inBytes[r] = recv[r].size() * rowBytes;
  }
  std::vector<char> in = alltoallv(out, outBytes, inBytes, counter);
  const char *cursor = in.data();
  for (int r = 0; r < n; ++r)
    fields([&](auto &column) { cursor = unpack(column, recv[r], cursor); });
}

} // namespace detail

/// Keeps only the owned particles.
template <typename Particles> void dropGhosts(Particles &P, HaloPlan &plan) {
  backend::keepRows(P, plan.owned);
  plan.ownAll(P.size());
}

/// Moves every particle to the rank that owns its cell. Call with no ghosts.
template <int D, typename Particles>
void migrate(Particles &P, const Domain<D> &domain, HaloPlan &plan) {
  const int n = ranks(), me = rank();
  std::vector<std::vector<Index>> send(n);
  std::vector<Index> keep;
  for (Index i = 0; i < P.size(); ++i) {
    int owner = domain.ownerAt(P.pos[i]);
    (owner == me ? keep : send[owner]).push_back(i);
  }
  std::vector<std::size_t> counts(n);
  for (int r = 0; r < n; ++r)
    counts[r] = send[r].size();
  std::vector<std::size_t> incoming = alltoallCounts(counts);
  std::size_t arriving = 0;
  for (int r = 0; r < n; ++r)
    arriving += r == me ? 0 : incoming[r];
  // Received particles go after the kept ones.
  std::vector<std::vector<Index>> recv(n);
  Index next = Index(keep.size());
  for (int r = 0; r < n; ++r)
    for (std::size_t k = 0; r != me && k < incoming[r]; ++k)
      recv[r].push_back(next++);
  send[me].clear();
  std::size_t total = keep.size() + arriving;
  // Pack (into one buffer, in rank order) before compacting, then compact,
  // grow and unpack; what was sent is freed before the columns grow.
  std::vector<char> out;
  std::size_t rowBytes = 0;
  P.forEachColumn([&](auto &column) { rowBytes += sizeof(column[0]); });
  out.reserve((P.size() - keep.size()) * rowBytes);
  std::vector<std::size_t> outBytes(n), inBytes(n);
  for (int r = 0; r < n; ++r) {
    P.forEachColumn([&](auto &column) { detail::pack(column, send[r], out); });
    outBytes[r] = send[r].size() * rowBytes;
    inBytes[r] = recv[r].size() * rowBytes;
  }
  std::vector<char> in = alltoallv(out, outBytes, inBytes, traffic().migration);
  std::vector<char>().swap(out);
  backend::keepRows(P, keep);
  P.forEachColumn([&](auto &column) { column.resize(total); });
  const char *cursor = in.data();
  for (int r = 0; r < n; ++r)
    P.forEachColumn([&](auto &column) { cursor = detail::unpack(column, recv[r], cursor); });
  plan.ownAll(total);
}

/// Before a new neighbour search: drops the halo, rebalances the domain when
/// the busiest rank spent more than `tolerance` times the mean time in
/// particle loops since the last balance (judged over `interval` searches at
/// least, so that one noisy step does not move particles), and migrates.
template <int D, typename Particles>
void redistribute(Particles &P, Domain<D> &domain, HaloPlan &plan, double tolerance = 1.1,
                  int interval = 4) {
  dropGhosts(P, plan);
  if (domain.searchesSinceBalance()++ >= interval) {
    const double busy = busySeconds();
    const double busiest = allreduceMax(busy), total = allreduceSum(busy);
    if (busiest > tolerance * total / ranks()) {
      std::vector<typename Domain<D>::Cell> cells(P.size());
      for (Index i = 0; i < P.size(); ++i)
        cells[i] = domain.cellOf(Vec<double, D>(P.pos[i]));
      domain.balance(cells, busy);
      busySeconds() = 0.0;
    }
  }
  migrate(P, domain, plan);
}

namespace detail {

/// After the copies received `fields` (ids among them): kept rows take the
/// columns `carried` visits from their previous copies, new rows receive
/// them; then `history` remembers the ids sent and received.
template <typename Particles, typename Carried>
void completeNewRows(Particles &P, const std::vector<std::vector<Index>> &send,
                     const std::vector<std::vector<Index>> &recv, Carried carried,
                     HaloHistory &history) {
  const int n = ranks();
  std::vector<std::vector<Index>> sendNew(n), recvNew(n);
  std::vector<std::pair<Index, std::size_t>> kept;
  for (int r = 0; r < n; ++r) {
    for (Index i : send[r])
      if (!history.wasSent(r, P.id[i]))
        sendNew[r].push_back(i);
    for (Index q : recv[r]) {
      const std::int64_t k = history.stashed(r, P.id[q]);
      if (k < 0)
        recvNew[r].push_back(q);
      else
        kept.emplace_back(q, std::size_t(k));
    }
  }
  restoreStashed(history, kept, carried);
  // Every rank visits the same columns: all skip the transfer, or none.
  bool any = false;
  carried([&](auto &) { any = true; });
  if (any)
    transfer(sendNew, recvNew, carried, traffic().halo);
  history.sent.assign(n, {});
  for (int r = 0; r < n; ++r) {
    for (Index i : send[r])
      history.sent[r].push_back(P.id[i]);
    std::sort(history.sent[r].begin(), history.sent[r].end());
  }
  history.received.clear();
  history.stash.clear();
  history.stashRows = 0;
}

} // namespace detail

/// Builds the halo for a new neighbour search: every owned particle (or local
/// periodic image) that can pair with a particle of another rank's cell
/// (pair_reach.hpp) is copied there, with the columns `fields` visits (id and
/// pos must be among them); a copy that is not kept (halo_history.hpp) also
/// with those `carried` visits, which a kept one takes from its previous
/// copy. Call after redistribute and addImages: positions
/// [0, plan.owned.size()) are owned, the rest up to P.size() are images.
template <int D, typename Particles, typename SmoothingLength, typename Fields, typename Carried>
void buildHalo(Particles &P, const Domain<D> &domain, const RowReach<SmoothingLength> &reachOf,
               const ::wash::detail::Box &box, HaloPlan &plan, Fields fields, Carried carried,
               HaloHistory &history) {
  const int n = ranks(), me = rank();
  const double radius = reachOf.at.reach;
  const std::size_t owned = P.size(); // senders: owned particles and images
  using Cell = typename Domain<D>::Cell;
  const double cellSize = domain.cellSize();
  // The cells the box [p - radius, p + radius] overlaps, [from, to] per axis.
  auto stencil = [&](const Vec<double, D> &p, Cell &from, Cell &to) {
    for (int a = 0; a < D; ++a) {
      from[a] = wash::detail::cellCoordinate(p.at(a) - radius, cellSize);
      to[a] = wash::detail::cellCoordinate(p.at(a) + radius, cellSize);
    }
  };
  // Every stencil lies in [lo, hi]: the stencil's bounds are monotone in p,
  // so those of the lowest and highest coordinates bound them all.
  Vec<double, D> low, high;
  for (int a = 0; a < D; ++a) {
    *low[a] = std::numeric_limits<double>::infinity();
    *high[a] = -std::numeric_limits<double>::infinity();
  }
  for (Index i = 0; i < owned; ++i) {
    const Vec<double, D> p(P.pos[i]);
    for (int a = 0; a < D; ++a) {
      *low[a] = std::min(low.at(a), p.at(a));
      *high[a] = std::max(high.at(a), p.at(a));
    }
  }
  Cell lo, hi, from, to;
  stencil(low, lo, to);
  stencil(high, from, hi);
  // Owners of the cells around this rank's particles, computed once per cell
  // when they span few enough cells.
  std::size_t cells = 1;
  for (int a = 0; a < D && owned; ++a)
    cells *= std::size_t(hi[a] - lo[a] + 1);
  const bool dense = owned > 0 && cells <= 8 * owned + 64;
  auto denseIndex = [&](const Cell &cell) {
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a)
      index = index * std::size_t(hi[a] - lo[a] + 1) + std::size_t(cell[a] - lo[a]);
    return index;
  };
  std::vector<int> ownerCache(dense ? cells : 0, -1);
  auto inBox = [&](const Cell &cell) {
    for (int a = 0; a < D; ++a)
      if (cell[a] < lo[a] || cell[a] > hi[a])
        return false;
    return true;
  };
  auto ownerOf = [&](const Cell &cell) {
    if (!dense || !inBox(cell))
      return domain.ownerOf(cell);
    int &owner = ownerCache[denseIndex(cell)];
    if (owner < 0)
      owner = domain.ownerOf(cell);
    return owner;
  };
  // A particle's stencil lies within `reach` cells of its own cell (one more
  // than the radius needs, for rounding). If this rank owns all of those
  // cells, the particle is sent nowhere: decided once per cell, so interior
  // particles skip the walk below.
  const std::int64_t reach = static_cast<std::int64_t>(std::ceil(radius / cellSize)) + 1;
  std::vector<signed char> interiorCache(dense ? cells : 0, -1);
  auto interior = [&](const Cell &own) {
    signed char &known = interiorCache[denseIndex(own)];
    if (known >= 0)
      return known == 1;
    Cell first, last;
    for (int a = 0; a < D; ++a) {
      first[a] = std::max(lo[a], own[a] - reach);
      last[a] = std::min(hi[a], own[a] + reach);
    }
    known = 1;
    forEachCellIn(first, last, [&](const Cell &x) {
      known = ownerOf(x) == me;
      return known == 1;
    });
    return known == 1;
  };
  const CellReach<D> theirs = exchangeBoundaryReach(
      P, plan.owned, domain, reachOf, box, reach, ownerOf,
      [&](const Cell &cell) { return dense && interior(cell); });
  std::vector<std::vector<Index>> send(n);
  std::vector<int> seen;
  for (Index i = 0; i < owned; ++i) {
    const Vec<double, D> p(P.pos[i]);
    if (dense && interior(domain.cellOf(p)))
      continue;
    stencil(p, from, to);
    seen.assign(1, me);
    const double own = reachOf.sender(i);
    forEachCellIn(from, to, [&](const Cell &cell) {
      const int owner = ownerOf(cell);
      if (std::find(seen.begin(), seen.end(), owner) != seen.end())
        return true;
      const double largest = theirs.largestAt(domain.keyOf(cell));
      if (largest >= 0.0 && withinOfCell<D>(p, cell, cellSize, std::max(own, largest))) {
        seen.push_back(owner);
        send[owner].push_back(i);
      }
      return true;
    });
  }
  std::vector<std::size_t> counts(n);
  for (int r = 0; r < n; ++r)
    counts[r] = send[r].size();
  std::vector<std::size_t> incoming = alltoallCounts(counts);
  std::vector<std::vector<Index>> recv(n);
  Index next = Index(owned);
  for (int r = 0; r < n; ++r)
    for (std::size_t k = 0; k < incoming[r]; ++k)
      recv[r].push_back(next++);
  P.forEachColumn([&](auto &column) { column.resize(next); });
  detail::transfer(send, recv, fields, traffic().halo);
  detail::completeNewRows(P, send, recv, carried, history);
  plan.send = std::move(send);
  plan.recv = std::move(recv);
  plan.ghosts = next - owned;
}

/// Refreshes the local images and then the halo copies of the columns `fields` visits.
template <typename Fields> void exchange(const HaloPlan &plan, Fields fields) {
  backend::refreshImages(plan, fields);
  detail::transfer(plan.send, plan.recv, fields, traffic().halo);
}

} // namespace wash::mpi
