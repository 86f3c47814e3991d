//===- HaloExchange.cpp ---------------------------------------------------===//
#include "wash/translator/Plan/HaloExchange.h"

namespace wash::tr {

std::vector<KernelHalo> planHalos(const std::vector<Kernel> &Kernels,
                                  const std::vector<SearchGroup> &Searches) {
  std::vector<KernelHalo> Result(Kernels.size());
  // Fields whose halo copies are current, walking one iteration in order.
  // Every iteration starts a new search, so one walk gives the steady state.
  FieldSet Current;
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    KernelHalo &H = Result[I];
    if (K.Kind == KernelKind::Init)
      continue;
    if (K.Kind == KernelKind::Force) {
      H.Fields = K.NeighbourReads;
      H.Fields.insert("pos");
      bool Rebuild = K.SearchGroup < 0 || Searches.at(K.SearchGroup).Kernels.front() == I;
      if (Rebuild)
        Current.clear();
      for (const std::string &F : H.Fields)
        if (!Current.count(F))
          H.Sends.insert(F);
      Current.insert(H.Sends.begin(), H.Sends.end());
    }
    for (const std::string &F : K.OwnWrites)
      Current.erase(F);
  }
  return Result;
}

} // namespace wash::tr
