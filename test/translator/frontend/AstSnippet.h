//===- AstSnippet.h - Frontend tests on ten-line programs -------*- C++ -*-===//
//
// Parses a snippet (a whole simulation file, `#include <wash/wash.hpp>` and
// all) with the translator's own parser and hands the AST to the test, with
// helpers to find the declarations and calls it is about.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Expr.h"

#include <functional>
#include <string>
#include <vector>

namespace wash::tr::test {

/// Parses Code as a simulation file and calls Body with its AST; false (and
/// a gtest failure) when clang rejects it.
bool withAst(const std::string &Code,
             const std::function<void(clang::ASTContext &, Diagnoser &)> &Body);

/// The definition of the function named Name in the snippet, or nullptr.
const clang::FunctionDecl *function(clang::ASTContext &Ctx, const std::string &Name);

/// Every call in the snippet of a function named Callee, in source order
/// (template instantiations and lambda bodies included).
std::vector<const clang::CallExpr *> calls(clang::ASTContext &Ctx, const std::string &Callee);

/// The I-th argument of the Nth call of Callee.
const clang::Expr *argument(clang::ASTContext &Ctx, const std::string &Callee, unsigned N,
                            unsigned I);

} // namespace wash::tr::test
