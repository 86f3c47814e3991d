//===- ParticleRoles.h - which particle an expression denotes ---*- C++ -*-===//
//
// The role lattice of InferAccesses: a set of bits saying what a value of
// particle type may denote. Roles only grow (a variable assigned both the own
// particle and a neighbour has both), which keeps the analysis conservative.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Expr.h"
#include "llvm/ADT/DenseMap.h"
#include <functional>
#include <optional>

namespace wash::tr {

using Roles = unsigned;
enum : Roles {
  RoleOwn = 1,       ///< The kernel's own particle (or one an init kernel created).
  RoleNeighbour = 2, ///< A neighbour, or a pointer to one.
  RoleList = 4,      ///< The neighbour vector.
  RoleIter = 8,      ///< An iterator or pointer into the neighbour vector.
};

/// What dereferencing (or indexing) a value with roles R yields.
inline Roles derefRoles(Roles R) {
  return (R & (RoleList | RoleIter) ? RoleNeighbour : 0) | (R & (RoleOwn | RoleNeighbour));
}

/// Roles of expressions, given roles of variables (Lookup) and of calls
/// already analysed (CallRoles, for calls into user code). Containers,
/// iterators, casts and copies are handled here, without analysing calls.
class RoleEvaluator {
public:
  using VarLookup = std::function<Roles(const clang::ValueDecl *)>;
  using CallLookup = std::function<std::optional<Roles>(const clang::CallExpr *)>;

  RoleEvaluator(VarLookup Vars, CallLookup Calls)
      : Vars(std::move(Vars)), Calls(std::move(Calls)) {}

  Roles of(const clang::Expr *E) const;
  /// The role of a call into the standard library (vector and iterator
  /// operations, std::begin and friends) or of wash::create_particle.
  Roles ofLibraryCall(const clang::CallExpr *CE) const;

private:
  VarLookup Vars;
  CallLookup Calls;
};

} // namespace wash::tr
