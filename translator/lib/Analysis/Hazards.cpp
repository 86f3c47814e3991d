//===- Hazards.cpp --------------------------------------------------------===//
#include "wash/translator/Analysis/Hazards.h"

#include <algorithm>
#include <iterator>

namespace wash::tr {

bool writesAndReadsDisjointTypes(const Kernel &K) {
  // Each particle has exactly one type, and a registration names one type
  // or every type (""): two named types are disjoint when they differ.
  return !K.ParticleType.empty() && !K.NeighbourType.empty() && K.ParticleType != K.NeighbourType;
}

std::vector<KernelHazards> findHazards(const std::vector<Kernel> &Kernels) {
  std::vector<KernelHazards> Result(Kernels.size());
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    if (K.Kind != KernelKind::Force)
      continue;
    FieldSet Both;
    std::set_intersection(K.OwnWrites.begin(), K.OwnWrites.end(), K.NeighbourReads.begin(),
                          K.NeighbourReads.end(), std::inserter(Both, Both.end()));
    (writesAndReadsDisjointTypes(K) ? Result[I].DisjointTypes : Result[I].Snapshot) =
        std::move(Both);
  }
  return Result;
}

} // namespace wash::tr
