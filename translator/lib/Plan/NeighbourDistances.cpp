//===- NeighbourDistances.cpp ---------------------------------------------===//
#include "wash/translator/Plan/NeighbourDistances.h"

#include <algorithm>

namespace wash::tr {

void planNeighbourDistances(Model &M) {
  const bool ForceWritesPos = std::any_of(M.Kernels.begin(), M.Kernels.end(), [](const Kernel &K) {
    return K.Kind == KernelKind::Force && K.OwnWrites.count("pos");
  });
  if (M.Sim.Precision != "double" || M.searchesBySmoothingLength() || ForceWritesPos)
    M.Distances.clear();
}

} // namespace wash::tr
