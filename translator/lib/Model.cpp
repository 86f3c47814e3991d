//===- Model.cpp - model helpers and the diagnostic tables ----------------===//
#include "wash/translator/Model.h"
#include "wash/translator/WashApiTable.h"

#include <algorithm>

namespace wash::tr {

DiagLevel diagLevel(DiagId Id) {
  switch (Id) {
#define WASH_DIAG(Name, Level, Message)                                                            \
  case DiagId::Name:                                                                               \
    return DiagLevel::Level;
#include "wash/translator/DiagnosticKinds.def"
  }
  return DiagLevel::Error;
}

const char *diagMessage(DiagId Id) {
  switch (Id) {
#define WASH_DIAG(Name, Level, Message)                                                            \
  case DiagId::Name:                                                                               \
    return Message;
#include "wash/translator/DiagnosticKinds.def"
  }
  return "";
}

const char *forceKindName(ForceKind K) { return K == ForceKind::Scalar ? "scalar" : "vector"; }

const char *kernelKindName(KernelKind K) {
  switch (K) {
  case KernelKind::Init:
    return "init";
  case KernelKind::Update:
    return "update";
  case KernelKind::Force:
    return "force";
  case KernelKind::Void:
    return "void";
  case KernelKind::Reduction:
    return "reduction";
  }
  return "?";
}

const std::vector<std::string> &builtinFieldNames() {
  static const std::vector<std::string> Names = [] {
    std::vector<std::string> N;
    for (const BuiltinField &F : builtinFields())
      N.push_back(F.Name);
    return N;
  }();
  return Names;
}

const Field *Model::findField(const std::string &Name) const {
  for (const Field &F : Fields)
    if (F.Name == Name)
      return &F;
  return nullptr;
}

int Model::typeIndex(const std::string &Name) const {
  for (unsigned T = 0; T < Types.size(); ++T)
    if (Types[T].Name == Name)
      return int(T);
  return -1;
}

bool Model::hasErrors() const {
  return std::any_of(Findings.begin(), Findings.end(),
                     [](const Finding &F) { return diagLevel(F.Id) == DiagLevel::Error; });
}

} // namespace wash::tr
