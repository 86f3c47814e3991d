//===- ResolveFields.cpp --------------------------------------------------===//
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/WashApiTable.h"

#include <algorithm>

namespace wash::tr {

static Field builtin(const BuiltinField &B, unsigned Dim) {
  Field F;
  F.Name = B.Name;
  F.Origin = FieldOrigin::Builtin;
  F.Kind = B.storage();
  F.Dim = F.Kind == ForceKind::Vector ? Dim : 1;
  F.ReadOnly = !B.settable();
  return F;
}

static Finding mismatch(const Field &F, const Access &A) {
  Finding R{DiagId::ForceKindMismatch,
            A.Pos,
            {F.Name, forceKindName(F.Kind), forceKindName(*A.Kind)},
            {}};
  if (F.Origin == FieldOrigin::Registered)
    R.Notes.push_back({DiagId::NoteRegisteredHere, F.Pos, {F.Name}, {}});
  else
    R.Notes.push_back({DiagId::NoteFirstUsedHere, F.Pos, {F.Name, forceKindName(F.Kind)}, {}});
  return R;
}

ResolvedFields resolveFields(unsigned Dim, const std::vector<ForceRegistration> &Forces,
                             const std::vector<Kernel> &Kernels, bool Typed) {
  ResolvedFields Result;
  std::vector<Field> &Fields = Result.Fields;
  for (const BuiltinField &B : builtinFields())
    Fields.push_back(builtin(B, Dim));
  if (Typed) {
    Field Type;
    Type.Name = TypeField;
    Fields.push_back(Type); // a builtin scalar: the type's index
  }
  for (const ForceRegistration &R : Forces) {
    Field F;
    F.Name = R.Name;
    F.Origin = FieldOrigin::Registered;
    F.Kind = R.Kind;
    F.Dim = R.Kind == ForceKind::Vector ? Dim : 1;
    F.Pos = R.Pos;
    Fields.push_back(F);
  }

  // Kernels are stored in registration order; init kernels run first, so
  // visit them first to find the use that creates a force at run time.
  std::vector<const Kernel *> Order;
  for (const Kernel &K : Kernels)
    if (K.Kind == KernelKind::Init)
      Order.push_back(&K);
  for (const Kernel &K : Kernels)
    if (K.Kind != KernelKind::Init)
      Order.push_back(&K);

  std::vector<SourcePos> Reported;
  for (const Kernel *K : Order) {
    for (const Access &A : K->Accesses) {
      if (!A.Kind)
        continue;
      auto It = std::find_if(Fields.begin(), Fields.end(), [&](const Field &F) {
        return F.Origin != FieldOrigin::Builtin && F.Name == A.Field;
      });
      if (It == Fields.end()) {
        Field F;
        F.Name = A.Field;
        F.Origin = FieldOrigin::Created;
        F.Kind = *A.Kind;
        F.Dim = F.Kind == ForceKind::Vector ? Dim : 1;
        F.Pos = A.Pos;
        Fields.push_back(F);
        Result.Findings.push_back(
            {DiagId::ForceCreated, A.Pos, {F.Name, forceKindName(F.Kind)}, {}});
        continue;
      }
      // The same helper may be reached from several kernels: report a
      // mismatching call once.
      if (It->Kind != *A.Kind &&
          std::find(Reported.begin(), Reported.end(), A.Pos) == Reported.end()) {
        Reported.push_back(A.Pos);
        Result.Findings.push_back(mismatch(*It, A));
      }
    }
  }
  // A force named like the type column, registered or created on first use,
  // would collide with it in the storage and in every output file.
  if (Typed)
    for (const Field &F : Fields)
      if (F.Origin != FieldOrigin::Builtin && F.Name == TypeField)
        Result.Findings.push_back({DiagId::ParticleTypeNameClash, F.Pos, {}, {}});
  return Result;
}

} // namespace wash::tr
