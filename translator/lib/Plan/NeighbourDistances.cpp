//===- NeighbourDistances.cpp ---------------------------------------------===//
#include "wash/translator/Plan/NeighbourDistances.h"

#include <algorithm>

namespace wash::tr {

std::vector<DistanceUse> planNeighbourDistances(const std::vector<DistanceUse> &Found,
                                                const Settings &Sim,
                                                const std::vector<Kernel> &Kernels) {
  const bool ForceWritesPos = std::any_of(Kernels.begin(), Kernels.end(), [](const Kernel &K) {
    return K.Kind == KernelKind::Force && K.OwnWrites.count("pos");
  });
  if (Sim.Precision != "double" || Sim.searchesBySmoothingLength() || ForceWritesPos)
    return {};
  return Found;
}

} // namespace wash::tr
