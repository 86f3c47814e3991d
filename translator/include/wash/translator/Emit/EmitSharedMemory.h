//===- EmitSharedMemory.h - the serial and OpenMP programs ------*- C++ -*-===//
//
// The parts of a serial or OpenMP program that do not come from the user's
// source: the storage header it includes in place of <wash/wash.hpp>, and the
// driver appended after the user's code. Clang-free.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Model.h"

#include <string>
#include <vector>

namespace wash::tr {

/// The first line of every generated file.
std::string generatedBanner(const CodePlan &Plan, const std::string &CommentLeader = "//");

/// `<stem>.wash.hpp`: columns of the live fields, snapshot accessors, and
/// the declarations of the generated create_particle and start.
std::string emitStorageHeader(const Model &M, const CodePlan &Plan);

/// The run: create_particle, the neighbour search, output frames and start(),
/// calling Callees[K] for Model::Kernels[K] (names valid at namespace scope).
std::string emitSharedMemoryDriver(const Model &M, const CodePlan &Plan,
                                   const std::vector<std::string> &Callees);

} // namespace wash::tr
