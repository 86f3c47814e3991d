//===- Hazards.cpp --------------------------------------------------------===//
#include "wash/translator/Analysis/Hazards.h"

#include <algorithm>
#include <iterator>

namespace wash::tr {

std::vector<FieldSet> findHazards(const std::vector<Kernel> &Kernels) {
  std::vector<FieldSet> Result(Kernels.size());
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    if (K.Kind != KernelKind::Force)
      continue;
    std::set_intersection(K.OwnWrites.begin(), K.OwnWrites.end(), K.NeighbourReads.begin(),
                          K.NeighbourReads.end(), std::inserter(Result[I], Result[I].end()));
  }
  return Result;
}

} // namespace wash::tr
