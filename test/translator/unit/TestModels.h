//===- TestModels.h - small models for the unit tests -----------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr::test {

inline Access own(const std::string &F, Mode M, unsigned Line = 1) {
  return {F, Target::Own, M, std::nullopt, {"sim.cpp", Line, 1}};
}
inline Access neighbour(const std::string &F, unsigned Line = 1) {
  return {F, Target::Neighbour, Mode::Read, std::nullopt, {"sim.cpp", Line, 1}};
}
inline Access force(const std::string &F, ForceKind K, Mode M, unsigned Line) {
  return {F, Target::Own, M, K, {"sim.cpp", Line, 3}};
}
inline Kernel kernel(KernelKind K, const std::string &Name, std::vector<Access> As) {
  Kernel R;
  R.Kind = K;
  R.Function = Name;
  R.Accesses = std::move(As);
  return R;
}

} // namespace wash::tr::test
