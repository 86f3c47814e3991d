//===- HaloExchange.cpp ---------------------------------------------------===//
#include "wash/translator/Plan/HaloExchange.h"

namespace wash::tr {

void planHalos(Model &M) {
  // Fields whose halo copies are current, walking one iteration in order.
  // Every iteration starts a new search, so one walk gives the steady state.
  FieldSet Current;
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    Kernel &K = M.Kernels[I];
    K.HaloFields.clear();
    K.HaloSends.clear();
    if (K.Kind == KernelKind::Init)
      continue;
    if (K.Kind == KernelKind::Force) {
      K.HaloFields = K.NeighbourReads;
      K.HaloFields.insert("pos");
      bool Rebuild = K.SearchGroup < 0 || M.Searches.at(K.SearchGroup).Kernels.front() == I;
      if (Rebuild)
        Current.clear();
      for (const std::string &F : K.HaloFields)
        if (!Current.count(F))
          K.HaloSends.insert(F);
      Current.insert(K.HaloSends.begin(), K.HaloSends.end());
    }
    for (const std::string &F : K.OwnWrites)
      Current.erase(F);
  }
}

} // namespace wash::tr
