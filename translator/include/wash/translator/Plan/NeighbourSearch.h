//===- NeighbourSearch.h - sharing neighbour searches -----------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

struct SearchPlan {
  std::vector<SearchGroup> Searches; ///< Model::Searches.
  /// Kernel::SearchGroup of each kernel, in order: an index into Searches
  /// for force kernels, -1 for the others.
  std::vector<int> GroupOf;
};

/// Groups force kernels that can share one neighbour search. Force kernel B
/// reuses the lists of the force kernel A before it in the same iteration if
/// neither A (on its own particle) nor any update kernel between A and B
/// writes pos (nor, with SearchesBySmoothingLength, smoothing_length). The
/// first force kernel of an iteration always searches: the update kernels
/// that end the previous iteration may move particles. Reads the kernels'
/// Kind and OwnWrites (summariseAccesses).
SearchPlan planNeighbourSearch(const std::vector<Kernel> &Kernels, bool SearchesBySmoothingLength);

} // namespace wash::tr
