//===- wash/backend/neighbour_table.hpp - lists kept for one search -*- C++ -*-===//
//
// Under the smoothing-length rule a neighbour list is sorted by id, which
// costs as much as finding it. The force kernels of one search (the translator
// groups kernels with no write to pos or smoothing_length between them) see
// the same lists, so the search builds every particle's list once and keeps
// them: each thread fills its own buffer for a contiguous share of the
// particles. Memory: the lists (4 bytes a neighbour) and two pointers a row.
// Under the influence-radius rule lists are rebuilt per kernel instead, from
// the cell order at no sorting cost, and nothing is kept.
// Under the symmetric rule a particle's candidates come from the largest
// support radius near it (CellGrid::nearbyLargest), and each is kept within
// its pair radius.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/neighbours.hpp>
#include <wash/backend/search_geometry.hpp>

#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace wash::backend {

template <int D, typename PosT> class NeighbourTable {
public:
  using List = Neighbours<D, PosT, StoredNeighbourRef>;

  /// The lists of the particles at `rows`, in ascending id order.
  template <typename RealT>
  void build(const CellGrid<D> &grid, const Column<PosT> &pos, const Column<std::uint64_t> &ids,
             const Column<RealT> &h, const SearchGeometry &g, const std::vector<Index> &rows) {
    const std::size_t n = rows.size();
#ifdef _OPENMP
    const int shares = omp_get_max_threads();
#else
    const int shares = 1;
#endif
    buffers_.resize(std::size_t(shares));
    begin_.assign(pos.size(), nullptr);
    end_.assign(pos.size(), nullptr);
    offset_.resize(n);
    if (g.symmetric) { // every row's support radius, squared, and its search's reach
      reach_.resize(pos.size());
      pairR2_.resize(pos.size());
      WASH_OMP(parallel for if(pos.size() >= parallelMinimum) schedule(static))
      for (std::size_t q = 0; q < pos.size(); ++q)
        reach_[q] = g.radiusOf(double(h[q]));
      grid.nearbyLargest(reach_.data(), g.reach, reach_);
      WASH_OMP(parallel for if(pos.size() >= parallelMinimum) schedule(static))
      for (std::size_t q = 0; q < pos.size(); ++q) {
        const double r = g.radiusOf(double(h[q]));
        pairR2_[q] = r * r;
      }
    }
    WASH_OMP(parallel for schedule(static, 1))
    for (int s = 0; s < shares; ++s) {
      const std::size_t from = n * std::size_t(s) / std::size_t(shares),
                        to = n * std::size_t(s + 1) / std::size_t(shares);
      std::vector<StoredNeighbourRef> &buffer = buffers_[std::size_t(s)];
      buffer.clear();
      for (std::size_t k = from; k < to; ++k) {
        const Index i = rows[k];
        offset_[k] = buffer.size();
        if (g.symmetric) {
          // A hair beyond the reach, so that the candidates' cells, rounded,
          // cover every pair radius (the pair test decides).
          List list(grid, pos, i, ids, reach_[i] * (1.0 + 0x1p-40), pairR2_[i], pairR2_.data());
          buffer.insert(buffer.end(), list.begin(), list.end());
        } else {
          List list(grid, pos, i, ids, g.radiusOf(double(h[i])));
          buffer.insert(buffer.end(), list.begin(), list.end());
        }
      }
      for (std::size_t k = from; k < to; ++k) { // the buffer has stopped moving
        begin_[rows[k]] = buffer.data() + offset_[k];
        end_[rows[k]] = buffer.data() + (k + 1 < to ? offset_[k + 1] : buffer.size());
      }
    }
  }

  /// The neighbours of the particle at row i (one of the rows built).
  List list(Index i) const { return List(begin_[i], end_[i]); }

private:
  std::vector<std::vector<StoredNeighbourRef>> buffers_;
  std::vector<const StoredNeighbourRef *> begin_, end_;
  std::vector<std::size_t> offset_;
  std::vector<double> reach_, pairR2_; // the symmetric rule's, per row
};

} // namespace wash::backend
