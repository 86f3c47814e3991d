//===- EmitDriver.h - the run of a generated program ------------*- C++ -*-===//
//
// One driver for every backend: it calls the backend type the storage header
// names (wash::<backend>::Backend<D>, backends/common/.../backend.hpp) and
// follows the model's plan step by step. What differs per backend is data in
// the plan (which columns a search or a refresh carries), not code here.
// Clang-free.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Model.h"

#include <string>
#include <vector>

namespace wash::tr {

/// The run: create_particle, the neighbour search, output frames and start(),
/// calling Callees[K] for Model::Kernels[K] (names valid at namespace scope).
std::string emitDriver(const Model &M, const CodePlan &Plan,
                       const std::vector<std::string> &Callees);

} // namespace wash::tr
