//===- HaloExchange.cpp ---------------------------------------------------===//
#include "wash/translator/Plan/HaloExchange.h"

namespace wash::tr {
namespace {

bool rebuildsHalo(const std::vector<Kernel> &Kernels, const std::vector<SearchGroup> &Searches,
                  unsigned I) {
  const Kernel &K = Kernels[I];
  return K.SearchGroup < 0 || Searches.at(K.SearchGroup).Kernels.front() == I;
}

/// The fields some force kernel reads through neighbours before any kernel
/// writes them, from kernel I on (its own reads first), round the iterations.
FieldSet readAhead(const std::vector<Kernel> &Kernels, unsigned I) {
  FieldSet Read, Written;
  for (unsigned Step = 0; Step < Kernels.size(); ++Step) {
    const Kernel &K = Kernels[(I + Step) % Kernels.size()];
    if (K.Kind == KernelKind::Init)
      continue;
    if (K.Kind == KernelKind::Force)
      for (const std::string &F : K.NeighbourReads)
        if (!Written.count(F))
          Read.insert(F);
    Written.insert(K.OwnWrites.begin(), K.OwnWrites.end());
  }
  return Read;
}

/// One iteration's walk from the fields current on every halo row at its
/// start (Current, updated to those at its end), filling Result.
void walkIteration(const std::vector<Kernel> &Kernels, const std::vector<SearchGroup> &Searches,
                   FieldSet &Current, std::vector<KernelHalo> &Result) {
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    const Kernel &K = Kernels[I];
    KernelHalo &H = Result[I];
    if (K.Kind == KernelKind::Init)
      continue;
    if (K.Kind == KernelKind::Force) {
      H = KernelHalo();
      H.Fields = K.NeighbourReads;
      H.Fields.insert("pos");
      for (const std::string &F : H.Fields)
        (Current.count(F) ? H.Current : H.Sends).insert(F);
      if (rebuildsHalo(Kernels, Searches, I)) {
        // The search places and orders every row by pos: it always travels.
        H.Sends.insert("pos");
        H.Current.erase("pos");
        H.NewRowSends = H.Fields;
        const FieldSet Ahead = readAhead(Kernels, I);
        for (const std::string &F : Current)
          if (Ahead.count(F))
            H.NewRowSends.insert(F);
        Current = H.NewRowSends;
      } else {
        Current.insert(H.Sends.begin(), H.Sends.end());
      }
    }
    for (const std::string &F : K.OwnWrites)
      Current.erase(F);
  }
}

} // namespace

std::vector<KernelHalo> planHalos(const std::vector<Kernel> &Kernels,
                                  const std::vector<SearchGroup> &Searches) {
  // The current fields only grow from one walk to the next (a walk is
  // monotone in them, and the first starts from none), so this ends within
  // one walk per field.
  std::vector<KernelHalo> Result(Kernels.size());
  FieldSet Current;
  for (;;) {
    FieldSet Start = Current;
    walkIteration(Kernels, Searches, Current, Result);
    if (Current == Start)
      return Result;
  }
}

} // namespace wash::tr
