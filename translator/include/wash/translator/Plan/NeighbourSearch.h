//===- NeighbourSearch.h - sharing neighbour searches -----------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// Groups force kernels that can share one neighbour search. Force kernel B
/// reuses the lists of the force kernel A before it in the same iteration if
/// neither A (on its own particle) nor any update kernel between A and B
/// writes pos. The first force kernel of an iteration always searches: the
/// update kernels that end the previous iteration may move particles. Fills
/// Model::Searches and Kernel::SearchGroup. Needs summariseAccesses.
void planNeighbourSearch(Model &M);

} // namespace wash::tr
