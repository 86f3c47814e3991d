//===- ParameterBindings.h - what a parameter is bound to ------*- C++ -*-===//
//
// A name (of a force, a variable, a type) may reach an API call through a
// helper's parameter. C++ binds that parameter to the caller's argument, or
// to its default when the caller passes none; the translator must read the
// same value. Two ways to know it:
//  - a CallContext: the chain of calls a walk followed to get here (main's
//    registration walk inlines every call), which binds each parameter
//    exactly;
//  - without one, the sole value: a parameter of a function whose every call
//    is visible (a free function never used other than by a direct call) is
//    bound to the value its calls agree on. A kernel's code is rewritten once
//    for every caller, so two calls binding different names cannot be
//    lowered; neither can a parameter whose callers are not all in sight.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/ASTContext.h"
#include "clang/AST/Expr.h"

#include <vector>

namespace wash::tr {

/// A call a walk followed, and the call that reached it.
struct CallContext {
  const clang::CallExpr *Call = nullptr;
  const clang::FunctionDecl *Callee = nullptr;
  const CallContext *Outer = nullptr;
};

/// The argument Call passes for parameter P of its callee (a
/// CXXDefaultArgExpr when it passes none), or nullptr when P is not one of
/// its callee's parameters. Member and operator calls are matched to the
/// callee's parameters, not to the object.
const clang::Expr *argumentFor(const clang::CallExpr *Call, const clang::FunctionDecl *Callee,
                               const clang::ParmVarDecl *P);

/// Every call in the program (user code, template instantiations included)
/// of P's function, when all of them are visible: the function is a free
/// function, not a template, and is never named other than as the callee of a
/// direct call. Empty when they are not (then nothing is known of P).
const std::vector<const clang::CallExpr *> &visibleCalls(const clang::ParmVarDecl *P,
                                                         clang::ASTContext &Ctx);

} // namespace wash::tr
