//===- Backends.h - the backends the translator can target ------*- C++ -*-===//
//
// One enumerator per line of backends/backends.def; everything else about a
// backend (its runtime type, its header, its CMake target) follows from its
// name, so the emitters never spell a backend out.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace wash::tr {

enum class Backend {
#define WASH_BACKEND(Enum, Name, Description, Distributed) Enum,
#include "backends.def"
#undef WASH_BACKEND
};

struct BackendInfo {
  Backend Id;
  const char *Name;        ///< --backend=<Name>, wash::<Name>::Backend, wash::<Name>
  const char *Description; ///< For --help.
  bool Distributed;        ///< Several processes, each with a share of the particles.
};

/// Every backend, in backends.def order.
const std::vector<BackendInfo> &allBackends();
const BackendInfo &backendInfo(Backend B);
const char *backendName(Backend B);
std::optional<Backend> backendNamed(const std::string &Name);

} // namespace wash::tr
