//===- wash/backend/periodic.hpp - local periodic images ---------*- C++ -*-===//
//
// Across a periodic face, a neighbour is the image of a particle shifted by the
// box length (docs/semantics.md). For a neighbour search the backends append
// image copies of the particles within reach of a face, with shifted
// positions and the same id, so that the ordinary cell search finds them in
// canonical order. Kernels run only over the real particles (`owned`).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/detail/box.hpp>
#include <wash/vec.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace wash::backend {

/// Which positions hold real particles, and which hold images of which.
struct Images {
  std::vector<Index> owned;          ///< real particles, ascending positions
  std::vector<Index> source, image;  ///< image[m] is a copy of source[m]

  /// Positions 0..n-1 are all real, and there are no images.
  void ownAll(std::size_t n) {
    owned.resize(n);
    std::iota(owned.begin(), owned.end(), Index(0));
    source.clear();
    image.clear();
  }

  /// Where each old position went when columns were reordered by `order`
  /// (new[k] = old[order[k]]).
  static std::vector<Index> inverse(const std::vector<Index> &order) {
    std::vector<Index> where(order.size());
    for (Index k = 0; k < order.size(); ++k)
      where[order[k]] = k;
    return where;
  }

  /// After columns were reordered by `order`: follow the positions.
  void permuted(const std::vector<Index> &order) { moved(inverse(order)); }

  /// The same, given inverse(order).
  void moved(const std::vector<Index> &where) {
    for (auto *list : {&source, &image})
      for (Index &p : *list)
        p = where[p];
    std::vector<char> real(where.size(), 0);
    for (Index p : owned)
      real[where[p]] = 1;
    owned.clear();
    for (Index k = 0; k < where.size(); ++k)
      if (real[k])
        owned.push_back(k);
  }
};

/// Calls visit(k) for every combination k of the shifts `shift` allows, a
/// shift per axis, 0 or shift[a], other than all zero: the images of a
/// point near the faces where shift[a] is +1 (near the low face: its image
/// lies past the high one) or -1. The lowest axis varies fastest.
template <int D, typename Visit> void forEachImageShift(const std::array<int, D> &shift, Visit visit) {
  std::array<int, D> k{};
  while (true) {
    int a = 0;
    while (a < D && (k[a] != 0 || shift[a] == 0))
      k[a] = 0, ++a;
    if (a == D)
      return;
    k[a] = shift[a];
    visit(k);
  }
}

/// Appends an image of every particle among `from` (positions) that can pair
/// with a particle across a periodic face, once per combination of faces it
/// is near, and records them. Its image across the low face of axis a lands
/// by the high face, where it pairs with a particle i only if it lies within
/// i's search radius (at most the largest by that face) or, under the
/// symmetric rule, within its own: 1.01 times the larger, a safe superset.
/// Under the influence-radius rule both are the radius. `combineMax`, if
/// given, takes the largest radius by a face over all processes.
template <int D, typename Particles, typename SmoothingLength>
void addImages(Particles &P, const std::vector<Index> &from, const detail::Box &box,
               const RowReach<SmoothingLength> &reachOf, Images &images,
               double (*combineMax)(double) = nullptr) {
  if (!box.anyPeriodic())
    return;
  const double reach = 1.01 * reachOf.at.reach;
  // byFace[a][0]: the largest search radius by the low face of axis a; [1] the high.
  std::array<std::array<double, 2>, D> byFace{};
  for (Index i : from)
    for (int a = 0; a < D; ++a) {
      const double x = double(P.pos[i].at(a));
      if (box.periodic[a] && x - box.lo[a] <= reach)
        byFace[a][0] = std::max(byFace[a][0], reachOf.search(i));
      if (box.periodic[a] && box.hi[a] - x <= reach)
        byFace[a][1] = std::max(byFace[a][1], reachOf.search(i));
    }
  for (int a = 0; a < D; ++a)
    for (double &largest : byFace[a])
      largest = combineMax ? combineMax(largest) : largest;
  for (Index i : from) {
    std::array<int, D> shift{}; // per axis: the image's shift, 0 for none
    const double own = reachOf.sender(i);
    for (int a = 0; a < D; ++a) {
      const double x = double(P.pos[i].at(a));
      if (box.periodic[a] && x - box.lo[a] <= std::min(reach, 1.01 * std::max(own, byFace[a][1])))
        shift[a] = 1;
      else if (box.periodic[a] &&
               box.hi[a] - x <= std::min(reach, 1.01 * std::max(own, byFace[a][0])))
        shift[a] = -1;
    }
    forEachImageShift<D>(shift, [&](const std::array<int, D> &k) {
      const Index copy = Index(P.size());
      P.forEachColumn([&](auto &column) {
        auto value = column[i];
        column.push_back(value);
      });
      for (int b = 0; b < D; ++b)
        if (k[b])
          *P.pos[copy][b] =
              decltype(P.pos[copy].at(b))(box.shifted(double(P.pos[i].at(b)), k[b], b));
      images.source.push_back(i);
      images.image.push_back(copy);
    });
  }
}

/// Brings the image copies of the columns `fields` visits up to date.
template <typename Fields> void refreshImages(const Images &images, Fields fields) {
  fields([&](auto &column) {
    for (std::size_t m = 0; m < images.image.size(); ++m)
      column[images.image[m]] = column[images.source[m]];
  });
}

/// Keeps only the real particles (their order is restored by the next cell sort).
template <typename Particles> void dropImages(Particles &P, Images &images) {
  keepRows(P, images.owned);
  images.ownAll(P.size());
}

/// Wraps the positions of the given particles into the box on periodic axes.
template <typename PosT>
void wrapPositions(Column<PosT> &pos, const std::vector<Index> &rows, const detail::Box &box) {
  if (!box.anyPeriodic())
    return;
  for (Index p : rows)
    for (int a = 0; a < PosT::dimension; ++a)
      if (box.periodic[a])
        *pos[p][a] = typename PosT::value_type(box.wrap(double(pos[p].at(a)), a));
}

} // namespace wash::backend
