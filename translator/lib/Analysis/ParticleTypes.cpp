//===- ParticleTypes.cpp --------------------------------------------------===//
#include "wash/translator/Analysis/ParticleTypes.h"

namespace wash::tr {

/// The types a kernel's accesses count for: Type's, or all.
static std::set<unsigned> typesOf(const std::string &Type, const std::vector<ParticleType> &Types) {
  std::set<unsigned> S;
  for (unsigned T = 0; T < Types.size(); ++T)
    if (Type.empty() || Types[T].Name == Type)
      S.insert(T);
  return S;
}

std::map<std::string, FieldTypeUse> fieldTypeUses(const std::vector<ParticleType> &Types,
                                                  const std::vector<Kernel> &Kernels) {
  std::map<std::string, FieldTypeUse> Uses;
  for (const Kernel &K : Kernels) {
    const bool Own = K.Kind != KernelKind::Init && K.Kind != KernelKind::Void;
    const std::set<unsigned> Self = typesOf(Own ? K.ParticleType : "", Types);
    const std::set<unsigned> Others = typesOf(K.NeighbourType, Types);
    for (const std::string &F : K.OwnReads)
      Uses[F].ReadFor.insert(Self.begin(), Self.end());
    for (const std::string &F : K.OwnWrites)
      Uses[F].WrittenFor.insert(Self.begin(), Self.end());
    for (const std::string &F : K.NeighbourReads)
      Uses[F].ReadFor.insert(Others.begin(), Others.end());
  }
  return Uses;
}

} // namespace wash::tr
