//===- AstQueries.h - the AST questions every Frontend pass asks -*- C++ -*-===//
//
// One answer to each question the passes share: what an expression is once
// the nodes that only convert, copy or parenthesise it are peeled off, and
// whether a variable is only ever read. A pass that asks its own way can
// disagree with the others about what a helper binds.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Expr.h"
#include "clang/AST/ExprCXX.h"

namespace wash::tr {

/// Which nodes peel() looks through, besides parentheses, implicit casts,
/// temporaries and full-expressions (which it always looks through).
struct PeelOptions {
  /// Explicit casts too (C, static_cast, const_cast...), not only implicit ones.
  bool ExplicitCasts = false;
  /// Functional casts (`std::string(s)`), even when other explicit casts are kept.
  bool FunctionalCasts = false;
  /// A default argument, to the default's expression.
  bool DefaultArguments = false;
  /// A std::initializer_list, to the array its elements live in.
  bool InitializerLists = false;
  /// A variable, to its initialiser (any variable with one).
  bool VariableInitialisers = false;
  /// Which constructions are copies of their first argument. Unset: copy and
  /// move constructors only.
  bool (*IsCopy)(const clang::CXXConstructExpr *) = nullptr;
};

/// E without the nodes Options says only convert, copy or name it.
const clang::Expr *peel(const clang::Expr *E, const PeelOptions &Options = {});

/// A construction taking one argument (copies, conversions) of any type.
bool constructsFromOneArgument(const clang::CXXConstructExpr *CE);
/// No construction: for PeelOptions::IsCopy, to stop at every constructor.
bool noConstruction(const clang::CXXConstructExpr *CE);

/// Every use of V in Body (lambda bodies included) only reads V: converted to
/// a value, bound to a parameter taken by value or const reference, or the
/// object of a const member function or operator.
bool onlyRead(const clang::ValueDecl *V, const clang::Stmt *Body);

} // namespace wash::tr
