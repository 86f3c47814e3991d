//===- PureFunctions.h - functions whose value is their arguments' -*- C++ -*-===//
//
// A call that findHoistable moves out of the pair loop runs once per row, for
// rows whose values the kernel may never use: only a function whose value
// depends on nothing but its arguments and constants, with no side effects
// and nothing undefined on odd values, may move.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Decl.h"
#include "clang/AST/Expr.h"
#include "clang/Basic/SourceManager.h"

#include <map>

namespace wash::tr {

/// An arithmetic type, not an enumeration (through references).
bool isArithmetic(clang::QualType T);

/// A <cmath> function (global or std::) without side effects that matter to
/// a value.
bool isMathFunction(const clang::FunctionDecl *FD, const clang::SourceManager &SM);

/// Whether a function's value depends only on its arguments and constants:
/// a body that writes only its own locals, reads no mutable global, calls
/// only such functions, has no loops (it runs for rows whose values the
/// kernel would never use) and nothing undefined on odd values.
class Purity {
public:
  explicit Purity(const clang::SourceManager &SM) : SM(SM) {}

  bool pure(const clang::FunctionDecl *FD);
  /// By value, or a const reference.
  static bool parameterReadOnly(clang::QualType T);
  /// Integer division, remainders and shifts can be undefined on values the
  /// kernel would never use; comma and pointer arithmetic are not values.
  static bool binaryAllowed(const clang::BinaryOperator *Bin);

private:
  bool stmt(const clang::Stmt *S, const clang::FunctionDecl *F);
  static bool castable(const clang::CastExpr *Cast);
  bool readable(const clang::ValueDecl *D, const clang::FunctionDecl *F) const;
  static bool writesLocal(const clang::Expr *E, const clang::FunctionDecl *F);

  const clang::SourceManager &SM;
  std::map<const clang::FunctionDecl *, bool> Known; ///< false while in progress
};

} // namespace wash::tr
