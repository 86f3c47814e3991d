//===- wash/detail/neighbour_search.hpp - canonical neighbour lists -*- C++ -*-===//
//
// The neighbours of particle i are the other particles j with
//   sum over axes a = x, y[, z] of (pos_j[a] - pos_i[a])^2  <=  radius^2
// (in double, axes summed in that order), visited in the canonical order:
// by the cell of j in a fixed grid of cell size `radius` anchored at the origin
// (cell coordinate floor(pos[a] / radius)), cells in lexicographic (z,) y, x
// order, and by ascending id inside a cell. The order depends only on the
// particles' positions and ids, never on storage order, threads or ranks.
// With per-particle support radii (search.hpp) the radius is particle i's own
// and the order is by ascending id; the cells are then only a search aid.
// (The symmetric rule searches with the largest radius and then keeps the
// pairs within their pair radius: runtime/src/reference/run.cpp.)
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/box.hpp>
#include <wash/detail/cell.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace wash::detail {

/// True if b lies within radius of a (the neighbour test above).
template <int D>
bool withinRadius(const Vec<double, D> &a, const Vec<double, D> &b, double radius) {
  double d2 = 0.0;
  for (int k = 0; k < D; ++k) {
    double d = b.at(k) - a.at(k);
    d2 += d * d;
  }
  return d2 <= radius * radius;
}

/// A cell list answering canonical neighbour queries. Simple rather than fast:
/// it is the reference the generated programs are checked against.
template <int D> class CellList {
public:
  /// Cell key with the slowest axis first, so that array order is (z,) y, x order.
  using Key = std::array<std::int64_t, D>;

  /// Cells of side `cellSize`: the influence radius, or with per-particle
  /// radii any positive size (the reference uses the largest radius).
  void build(const std::vector<Vec<double, D>> &positions, const std::vector<std::uint64_t> &ids,
             double cellSize) {
    positions_ = &positions;
    ids_ = &ids;
    cellSize_ = cellSize;
    cells_.clear();
    for (std::size_t i = 0; i < positions.size(); ++i)
      cells_[keyOf(positions[i])].push_back(i);
    for (auto &[key, members] : cells_)
      std::sort(members.begin(), members.end(),
                [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  }

  double cellSize() const { return cellSize_; }

  Key keyOf(const Vec<double, D> &p) const {
    Key key;
    for (int a = 0; a < D; ++a)
      key[D - 1 - a] = cellCoordinate(p.at(a), cellSize_);
    return key;
  }

  /// Indices of the neighbours of particle i, in canonical order.
  void neighbours(std::size_t i, std::vector<std::size_t> &out) const {
    neighbours(i, cellSize_, false, out);
  }

  /// The neighbours within `radius` of particle i, in cell order or, if
  /// `byId`, in ascending id order.
  void neighbours(std::size_t i, double radius, bool byId, std::vector<std::size_t> &out) const {
    out.clear();
    const Vec<double, D> &p = (*positions_)[i];
    forEachCandidate(p, radius, [&](std::size_t j) {
      if (j != i && withinRadius<D>(p, (*positions_)[j], radius))
        out.push_back(j);
    });
    if (byId)
      std::sort(out.begin(), out.end(),
                [&](std::size_t a, std::size_t b) { return (*ids_)[a] < (*ids_)[b]; });
  }

  /// The same in a box with periodic axes: each neighbour comes with the image
  /// position it is seen at (box.hpp's rule, each coordinate passed through
  /// `store`, the storage rounding), and the order is by the cell of that
  /// image, then id. Done by brute force over the 3^P shifts, obviously right.
  template <typename Store>
  void periodicNeighbours(std::size_t i, const Box &box, std::vector<std::size_t> &out,
                          std::vector<Vec<double, D>> &images, Store store) const {
    periodicNeighbours(i, cellSize_, false, box, out, images, store);
  }

  /// The same within `radius` of particle i, ordered by id if `byId`.
  template <typename Store>
  void periodicNeighbours(std::size_t i, double radius, bool byId, const Box &box,
                          std::vector<std::size_t> &out, std::vector<Vec<double, D>> &images,
                          Store store) const {
    struct Hit {
      Key key;
      std::uint64_t id;
      std::size_t j;
      Vec<double, D> image;
    };
    std::vector<Hit> hits;
    const Vec<double, D> &p = (*positions_)[i];
    std::array<int, D> k;
    k.fill(-1);
    for (int a = 0; a < D; ++a)
      if (!box.periodic[a])
        k[a] = 0;
    while (true) {
      Vec<double, D> query = p; // where j must be for its image x_j + kL to be near p
      for (int a = 0; a < D; ++a)
        *query[a] = box.shifted(p.at(a), -k[a], a);
      forEachCandidate(query, radius, [&](std::size_t j) {
        Vec<double, D> image = (*positions_)[j];
        for (int a = 0; a < D; ++a) {
          if (!box.periodic[a])
            continue;
          if (box.image(image.at(a), p.at(a), a) != k[a])
            return;
          if (k[a] != 0)
            *image[a] = store(box.shifted(image.at(a), k[a], a));
        }
        if (j != i && withinRadius<D>(p, image, radius))
          hits.push_back({keyOf(image), (*ids_)[j], j, image});
      });
      int a = D - 1;
      while (a >= 0 && (!box.periodic[a] || k[a] == 1)) {
        if (box.periodic[a])
          k[a] = -1;
        --a;
      }
      if (a < 0)
        break;
      ++k[a];
    }
    std::sort(hits.begin(), hits.end(), [byId](const Hit &x, const Hit &y) {
      return x.key != y.key && !byId ? x.key < y.key : x.id < y.id;
    });
    out.clear();
    images.clear();
    for (const Hit &h : hits) {
      out.push_back(h.j);
      images.push_back(h.image);
    }
  }

private:
  /// Calls f(j) for every particle in the cells overlapping [q - r, q + r] on
  /// each axis, in canonical order. The cells come from the interval rather
  /// than as +-1 so that rounding at cell borders cannot lose a neighbour.
  template <typename F> void forEachCandidate(const Vec<double, D> &q, double r, F f) const {
    Key lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[D - 1 - a] = cellCoordinate(q.at(a) - r, cellSize_);
      hi[D - 1 - a] = cellCoordinate(q.at(a) + r, cellSize_);
    }
    Key key = lo;
    while (true) {
      if (auto it = cells_.find(key); it != cells_.end())
        for (std::size_t j : it->second)
          f(j);
      int a = D - 1; // advance the fastest axis first
      while (a >= 0 && key[a] == hi[a])
        key[a] = lo[a], --a;
      if (a < 0)
        break;
      ++key[a];
    }
  }

  struct KeyHash {
    std::size_t operator()(const Key &k) const {
      std::size_t h = 0;
      for (std::int64_t c : k)
        h = h * 1000003u ^ std::hash<std::int64_t>()(c);
      return h;
    }
  };
  const std::vector<Vec<double, D>> *positions_ = nullptr;
  const std::vector<std::uint64_t> *ids_ = nullptr;
  double cellSize_ = 0.0;
  std::unordered_map<Key, std::vector<std::size_t>, KeyHash> cells_;
};

} // namespace wash::detail
