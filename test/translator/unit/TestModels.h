//===- TestModels.h - small models for the unit tests -----------*- C++ -*-===//
#pragma once

#include "wash/translator/Analysis/SummariseAccesses.h"
#include "wash/translator/Model.h"
#include "wash/translator/Plan/NeighbourSearch.h"

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

// The passes most others read, stored in the model as the pipeline does.

/// summariseAccesses: each kernel's OwnReads, OwnWrites and NeighbourReads.
inline void summarise(Model &M) {
  std::vector<AccessSets> Sets = summariseAccesses(M.Kernels, M.searchesBySmoothingLength());
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].OwnReads = Sets[I].OwnReads;
    M.Kernels[I].OwnWrites = Sets[I].OwnWrites;
    M.Kernels[I].NeighbourReads = Sets[I].NeighbourReads;
  }
}

/// planNeighbourSearch: Model::Searches and each kernel's SearchGroup.
inline void planSearches(Model &M) {
  SearchPlan P = planNeighbourSearch(M.Kernels, M.searchesBySmoothingLength());
  M.Searches = P.Searches;
  for (unsigned I = 0; I < M.Kernels.size(); ++I)
    M.Kernels[I].SearchGroup = P.GroupOf[I];
}

} // namespace wash::tr::test
