//===- EmitStorage.h - the storage header of a generated program -*- C++ -*-===//
//
// The header a generated program includes in place of <wash/wash.hpp>: one
// column per live field, the snapshots and the backend type. Clang-free.
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

} // namespace wash::tr
