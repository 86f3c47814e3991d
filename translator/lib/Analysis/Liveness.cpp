//===- Liveness.cpp -------------------------------------------------------===//
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/WashApiTable.h"

namespace wash::tr {

Liveness computeLiveness(const std::vector<Field> &Fields, const std::vector<Kernel> &Kernels) {
  Liveness Result;
  for (const Field &F : Fields) {
    bool Read = false, Written = false;
    for (const Kernel &K : Kernels) {
      Read |= K.OwnReads.count(F.Name) || K.NeighbourReads.count(F.Name);
      Written |= K.OwnWrites.count(F.Name) > 0;
    }
    const BuiltinField *B = F.Origin == FieldOrigin::Builtin ? builtinField(F.Name) : nullptr;
    FieldLiveness L;
    // A typed simulation's type column is always output.
    const bool TypeColumn = F.Origin == FieldOrigin::Builtin && F.Name == TypeField;
    L.Live = Read || Written || (B && B->AlwaysOutput) || TypeColumn;
    L.OutputOnly = Written && !Read;
    if (!L.Live && F.Origin == FieldOrigin::Registered)
      Result.Findings.push_back({DiagId::ForceUnused, F.Pos, {F.Name}, {}});
    Result.Fields.push_back(L);
  }
  return Result;
}

} // namespace wash::tr
