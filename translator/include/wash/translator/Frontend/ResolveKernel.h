//===- ResolveKernel.h - the function a registration names ------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Expr.h"

namespace wash::tr {

/// The definition of the function a kernel registration names (`&f` or `f`),
/// checked against the type the registration function's parameter points to;
/// null, after a diagnostic, if the argument is not a function name (a
/// variable, a lambda, a call), names a function this file does not define,
/// or one of the wrong type (reachable only through a cast).
const clang::FunctionDecl *resolveKernel(const clang::CallExpr *Registration, KernelKind Kind,
                                         clang::ASTContext &Ctx, Diagnoser &D);

} // namespace wash::tr
