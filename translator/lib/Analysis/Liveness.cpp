//===- Liveness.cpp -------------------------------------------------------===//
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/WashApiTable.h"

namespace wash::tr {

void computeLiveness(Model &M) {
  for (Field &F : M.Fields) {
    bool Read = false, Written = false;
    for (const Kernel &K : M.Kernels) {
      Read |= K.OwnReads.count(F.Name) || K.NeighbourReads.count(F.Name);
      Written |= K.OwnWrites.count(F.Name) > 0;
    }
    const BuiltinField *B = F.Origin == FieldOrigin::Builtin ? builtinField(F.Name) : nullptr;
    F.Live = Read || Written || (B && B->AlwaysOutput);
    F.OutputOnly = Written && !Read;
    if (!F.Live && F.Origin == FieldOrigin::Registered)
      M.Findings.push_back({DiagId::ForceUnused, F.Pos, {F.Name}, {}});
  }
}

} // namespace wash::tr
