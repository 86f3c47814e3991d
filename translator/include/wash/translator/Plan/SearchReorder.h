//===- SearchReorder.h - what a search's reordering must carry --*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// A search sorts the particles, and every column is reordered with them,
/// unless no old value of it can be read any more: some kernel later in the
/// same iteration sets it on every path (Kernel::AlwaysWrites) and no kernel
/// from the search up to and including that one reads it, on its particle or
/// through neighbours. The search itself reads pos (and smoothing_length),
/// the output reads id: those always move. Returns
/// Model::RewrittenAfterSearch, the fields for which that holds after every
/// search in Searches (planNeighbourSearch). Reads the kernels' OwnReads and
/// NeighbourReads (summariseAccesses) and AlwaysWrites (findAlwaysWrites).
FieldSet planSearchReorder(const std::vector<Kernel> &Kernels,
                           const std::vector<SearchGroup> &Searches);

} // namespace wash::tr
