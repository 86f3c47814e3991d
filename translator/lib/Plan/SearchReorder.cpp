//===- SearchReorder.cpp --------------------------------------------------===//
#include "wash/translator/Plan/SearchReorder.h"

namespace wash::tr {

/// Fields whose old values nothing reads after a search before kernel First.
static FieldSet rewrittenAfter(const std::vector<Kernel> &Kernels, unsigned First) {
  FieldSet Rewritten, Read;
  // Up to the end of the iteration: its last kernel is followed by output.
  for (unsigned I = First; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    Read.insert(K.OwnReads.begin(), K.OwnReads.end());
    Read.insert(K.NeighbourReads.begin(), K.NeighbourReads.end());
    if (!K.ParticleType.empty())
      continue; // it writes only its type's particles
    for (const std::string &F : K.AlwaysWrites)
      if (!Read.count(F))
        Rewritten.insert(F);
  }
  return Rewritten;
}

FieldSet planSearchReorder(const std::vector<Kernel> &Kernels,
                           const std::vector<SearchGroup> &Searches) {
  FieldSet Result;
  for (unsigned G = 0; G < Searches.size(); ++G) {
    FieldSet Here = rewrittenAfter(Kernels, Searches[G].Kernels.front());
    if (G == 0) {
      Result = Here;
      continue;
    }
    FieldSet Both;
    for (const std::string &F : Result)
      if (Here.count(F))
        Both.insert(F);
    Result = Both;
  }
  // The per-type rows come from the type column right after the sort.
  for (const char *Moved : {"pos", "smoothing_length", "id", "type"})
    Result.erase(Moved);
  return Result;
}

} // namespace wash::tr
