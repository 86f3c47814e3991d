//===- HaloExchange.cpp ---------------------------------------------------===//
#include "wash/translator/Plan/HaloExchange.h"

namespace wash::tr {

void planHalos(Model &M) {
  for (Kernel &K : M.Kernels) {
    K.HaloFields.clear();
    if (K.Kind != KernelKind::Force)
      continue;
    K.HaloFields = K.NeighbourReads;
    K.HaloFields.insert("pos");
  }
}

} // namespace wash::tr
