//===- SummariseAccesses.cpp ----------------------------------------------===//
#include "wash/translator/Analysis/SummariseAccesses.h"

namespace wash::tr {

std::vector<AccessSets> summariseAccesses(const std::vector<Kernel> &Kernels,
                                          bool SearchesBySmoothingLength, bool SymmetricSupport) {
  std::vector<AccessSets> Result;
  Result.reserve(Kernels.size());
  for (const Kernel &K : Kernels) {
    AccessSets S;
    for (const Access &A : K.Accesses) {
      if (A.On == Target::Own)
        (A.How == Mode::Read ? S.OwnReads : S.OwnWrites).insert(A.Field);
      else if (A.How == Mode::Read)
        S.NeighbourReads.insert(A.Field);
      // Neighbour writes are rejected by the frontend and never recorded.
    }
    // Under the smoothing-length rule the search reads h_i for each particle.
    if (K.Kind == KernelKind::Force && SearchesBySmoothingLength)
      S.OwnReads.insert("smoothing_length");
    // Under the symmetric rule it reads each candidate's h_j as well.
    if (K.Kind == KernelKind::Force && SearchesBySmoothingLength && SymmetricSupport)
      S.NeighbourReads.insert("smoothing_length");
    Result.push_back(std::move(S));
  }
  return Result;
}

} // namespace wash::tr
