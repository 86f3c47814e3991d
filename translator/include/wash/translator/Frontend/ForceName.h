//===- ForceName.h - evaluating and checking a force name ------*- C++ -*-===//
//
// A force name is the column name in every output file and an identifier in
// the generated code, so it must be one: [A-Za-z_][A-Za-z0-9_]*, and not a
// C++ keyword, a macro of the program or a builtin particle property.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ParameterBindings.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Expr.h"

#include <optional>
#include <string>

namespace wash::tr {

/// The force name NameArg (of add_force or a force accessor) evaluates to,
/// as C++ evaluates it. Reports ForceNameNotConstant or ForceNameInvalid at
/// the argument and returns nullopt when it cannot name a force.
std::optional<std::string> forceName(const clang::Expr *NameArg, clang::ASTContext &Ctx,
                                     Diagnoser &D, const CallContext *Context = nullptr);

} // namespace wash::tr
