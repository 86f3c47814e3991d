//===- AstRefs.h - the AST nodes behind the model ---------------*- C++ -*-===//
//
// The model holds no Clang types; the frontend passes that need the AST
// behind a model entry share it through this side table.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Decl.h"

#include <vector>

namespace wash::tr {

struct AstRefs {
  const clang::FunctionDecl *Main = nullptr;
  /// The definition of Model::Kernels[I]'s function.
  std::vector<const clang::FunctionDecl *> Kernels;
};

} // namespace wash::tr
