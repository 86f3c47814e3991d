//===- Hazards.cpp --------------------------------------------------------===//
#include "wash/translator/Analysis/Hazards.h"

#include <algorithm>
#include <iterator>

namespace wash::tr {

void findHazards(Model &M) {
  for (Kernel &K : M.Kernels) {
    K.Hazards.clear();
    if (K.Kind != KernelKind::Force)
      continue;
    std::set_intersection(K.OwnWrites.begin(), K.OwnWrites.end(), K.NeighbourReads.begin(),
                          K.NeighbourReads.end(), std::inserter(K.Hazards, K.Hazards.end()));
  }
}

} // namespace wash::tr
