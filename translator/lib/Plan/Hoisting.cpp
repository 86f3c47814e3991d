//===- Hoisting.cpp -------------------------------------------------------===//
#include "wash/translator/Plan/Hoisting.h"

#include <algorithm>

namespace wash::tr {

std::vector<HoistedExpr> planHoists(const std::vector<HoistedExpr> &Found,
                                    const std::vector<Kernel> &Kernels) {
  FieldSet Snapshotted;
  // Fields a force kernel writes and reads through neighbours, with or
  // without a snapshot: kept out of hoisting as before types were told apart.
  for (const Kernel &K : Kernels) {
    Snapshotted.insert(K.Hazards.begin(), K.Hazards.end());
    Snapshotted.insert(K.DisjointTypeWrites.begin(), K.DisjointTypeWrites.end());
  }
  std::vector<HoistedExpr> Kept;
  for (const HoistedExpr &H : Found) {
    bool Current = !H.Kernels.empty();
    for (unsigned I : H.Kernels) {
      const Kernel &K = Kernels.at(I);
      Current = Current && K.Kind == KernelKind::Force &&
                std::all_of(H.Reads.begin(), H.Reads.end(),
                            [&](const std::string &F) { return K.NeighbourReads.count(F); });
    }
    bool Written = std::any_of(H.Reads.begin(), H.Reads.end(),
                               [&](const std::string &F) { return Snapshotted.count(F); });
    if (Current && !Written)
      Kept.push_back(H);
  }
  return Kept;
}

} // namespace wash::tr
