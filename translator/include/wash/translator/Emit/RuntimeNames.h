//===- RuntimeNames.h - the runtime names generated code uses ---*- C++ -*-===//
//
// The emitters spell runtime names only through these constants, one per
// line of RuntimeNames.def, which a backend test checks against the runtime.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <string>

namespace wash::tr::rt {

#define WASH_RUNTIME_NAME(Id, Qualified) inline const std::string Id = #Qualified;
#include "wash/translator/Emit/RuntimeNames.def"
#undef WASH_RUNTIME_NAME

/// `wash::<backend>::Backend`: the runtime type of a backend (backends.def).
inline std::string backendType(const std::string &Backend) {
  return "wash::" + Backend + "::Backend";
}
/// The header that declares it.
inline std::string backendHeader(const std::string &Backend) {
  return "wash/" + Backend + "/backend.hpp";
}

} // namespace wash::tr::rt
