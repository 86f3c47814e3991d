//===- NeighbourSearch.cpp ------------------------------------------------===//
#include "wash/translator/Plan/NeighbourSearch.h"

namespace wash::tr {

SearchPlan planNeighbourSearch(const std::vector<Kernel> &Kernels, bool SearchesBySmoothingLength) {
  SearchPlan Plan;
  Plan.GroupOf.assign(Kernels.size(), -1);
  // What the last search depends on changed since it ran: at the start of an
  // iteration there is nothing to reuse.
  bool SearchStale = true;
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    if (K.Kind == KernelKind::Init)
      continue; // Init kernels run once, before the iteration loop.
    if (K.Kind == KernelKind::Force) {
      if (SearchStale)
        Plan.Searches.push_back({});
      Plan.GroupOf[I] = static_cast<int>(Plan.Searches.size()) - 1;
      Plan.Searches.back().Kernels.push_back(I);
      SearchStale = false;
    }
    // A search depends on positions and, by smoothing length, on h too.
    if (K.OwnWrites.count("pos") ||
        (SearchesBySmoothingLength && K.OwnWrites.count("smoothing_length")))
      SearchStale = true;
  }
  return Plan;
}

} // namespace wash::tr
