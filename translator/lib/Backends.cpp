//===- Backends.cpp - backends.def as a table -----------------------------===//
#include "wash/translator/Backends.h"

namespace wash::tr {

const std::vector<BackendInfo> &allBackends() {
  static const std::vector<BackendInfo> Table = {
#define WASH_BACKEND(Enum, Name, Description, Distributed)                                         \
  {Backend::Enum, #Name, Description, Distributed != 0},
#include "backends.def"
#undef WASH_BACKEND
  };
  return Table;
}

const BackendInfo &backendInfo(Backend B) { return allBackends().at(static_cast<size_t>(B)); }

const char *backendName(Backend B) { return backendInfo(B).Name; }

std::optional<Backend> backendNamed(const std::string &Name) {
  for (const BackendInfo &I : allBackends())
    if (Name == I.Name)
      return I.Id;
  return std::nullopt;
}

} // namespace wash::tr
