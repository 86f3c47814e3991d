//===- SearchReorder.cpp --------------------------------------------------===//
#include "wash/translator/Plan/SearchReorder.h"

namespace wash::tr {

/// Fields whose old values nothing reads after a search before kernel First.
static FieldSet rewrittenAfter(const Model &M, unsigned First) {
  FieldSet Rewritten, Read;
  // Up to the end of the iteration: its last kernel is followed by output.
  for (unsigned I = First; I < M.Kernels.size(); ++I) {
    const Kernel &K = M.Kernels[I];
    Read.insert(K.OwnReads.begin(), K.OwnReads.end());
    Read.insert(K.NeighbourReads.begin(), K.NeighbourReads.end());
    for (const std::string &F : K.AlwaysWrites)
      if (!Read.count(F))
        Rewritten.insert(F);
  }
  return Rewritten;
}

void planSearchReorder(Model &M) {
  M.RewrittenAfterSearch.clear();
  for (unsigned G = 0; G < M.Searches.size(); ++G) {
    FieldSet Here = rewrittenAfter(M, M.Searches[G].Kernels.front());
    if (G == 0) {
      M.RewrittenAfterSearch = Here;
      continue;
    }
    FieldSet Both;
    for (const std::string &F : M.RewrittenAfterSearch)
      if (Here.count(F))
        Both.insert(F);
    M.RewrittenAfterSearch = Both;
  }
  for (const char *Moved : {"pos", "smoothing_length", "id"})
    M.RewrittenAfterSearch.erase(Moved);
}

} // namespace wash::tr
