//===- NeighbourSearch.cpp ------------------------------------------------===//
#include "wash/translator/Plan/NeighbourSearch.h"

namespace wash::tr {

void planNeighbourSearch(Model &M) {
  M.Searches.clear();
  // What the last search depends on changed since it ran: at the start of an
  // iteration there is nothing to reuse.
  bool SearchStale = true;
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    Kernel &K = M.Kernels[I];
    K.SearchGroup = -1;
    if (K.Kind == KernelKind::Init)
      continue; // Init kernels run once, before the iteration loop.
    if (K.Kind == KernelKind::Force) {
      if (SearchStale)
        M.Searches.push_back({});
      K.SearchGroup = static_cast<int>(M.Searches.size()) - 1;
      M.Searches.back().Kernels.push_back(I);
      SearchStale = false;
    }
    // A search depends on positions and, by smoothing length, on h too.
    if (K.OwnWrites.count("pos") ||
        (M.searchesBySmoothingLength() && K.OwnWrites.count("smoothing_length")))
      SearchStale = true;
  }
}

} // namespace wash::tr
