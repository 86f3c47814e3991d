//===- WashApiTable.cpp - the tables of WashApi.def -----------------------===//
#include "wash/translator/WashApiTable.h"

#include <algorithm>
#include <vector>

namespace wash::tr {
namespace {

constexpr BuiltinField Fields[] = {
#define WASH_FIELD(Name, Kind, Getter, Setter, AlwaysOutput, Created)                              \
  {#Name, FieldKind::Kind, Getter, Setter, AlwaysOutput, Created},
#include "wash/translator/WashApi.def"
};

constexpr ApiCallInfo Calls[] = {
#define WASH_CALL(Name, Use, Lowering, MinArgs)                                                    \
  {ApiCall::Name, #Name, CallUse::Use, CallLowering::Lowering, MinArgs, std::nullopt},
#define WASH_KERNEL_CALL(Name, Kind, MinArgs)                                                      \
  {ApiCall::Name, #Name, CallUse::MainOnce, CallLowering::Drop, MinArgs, KernelKind::Kind},
#include "wash/translator/WashApi.def"
};

// apiCall(ApiCall) indexes Calls by enumerator.
constexpr bool callsInEnumOrder() {
  for (unsigned I = 0; I < std::size(Calls); ++I)
    if (static_cast<unsigned>(Calls[I].Id) != I)
      return false;
  return true;
}
static_assert(callsInEnumOrder());

std::vector<ParticleAccessor> makeAccessors() {
  std::vector<ParticleAccessor> A;
  for (const BuiltinField &F : Fields) {
    A.push_back({F.Getter, &F, Mode::Read, F.storage()});
    if (F.settable())
      A.push_back({F.Setter, &F, Mode::Write, F.storage()});
  }
#define WASH_FORCE_ACCESSOR(Method, How, Kind)                                                     \
  A.push_back({#Method, nullptr, Mode::How, ForceKind::Kind});
#define WASH_TYPE_ACCESSOR(Method, How)                                                            \
  A.push_back({#Method, nullptr, Mode::How, ForceKind::Scalar, /*IsType=*/true});
#include "wash/translator/WashApi.def"
  return A;
}

} // namespace

std::span<const BuiltinField> builtinFields() { return Fields; }

const BuiltinField *builtinField(std::string_view Name) {
  for (const BuiltinField &F : Fields)
    if (Name == F.Name)
      return &F;
  return nullptr;
}

bool ParticleAccessor::reads(std::string_view Name) const {
  return Field && How == Mode::Read && Name == Field->Name;
}

std::span<const ParticleAccessor> particleAccessors() {
  static const std::vector<ParticleAccessor> Accessors = makeAccessors();
  return Accessors;
}

std::optional<ParticleAccessor> decodeAccessor(std::string_view Method) {
  for (const ParticleAccessor &A : particleAccessors())
    if (Method == A.Method)
      return A;
  return std::nullopt;
}

std::span<const ApiCallInfo> apiCalls() { return Calls; }

const ApiCallInfo *apiCall(std::string_view Name) {
  for (const ApiCallInfo &C : Calls)
    if (Name == C.Name)
      return &C;
  return nullptr;
}

const ApiCallInfo &apiCall(ApiCall Id) { return Calls[static_cast<unsigned>(Id)]; }

} // namespace wash::tr
