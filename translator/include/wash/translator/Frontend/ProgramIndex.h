//===- ProgramIndex.h - the program, indexed once, and walks of it -*- C++ -*-===//
//
// Built once after parsing and shared by every Frontend pass:
//  - the one definition of the user's functions;
//  - the call graph: each direct call with the function it is made from,
//    and the functions something other than a free function's direct call
//    may run (members, lambdas, initialisers, functions whose address is
//    taken);
//  - one budget for every walk that follows calls into bodies.
// CallWalk is the only way a pass follows a call: its stack finds recursion,
// the index's budget bounds all walks of the program together, so a hostile
// call tree costs the same whichever pass meets it first.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/Expr.h"

#include <map>
#include <set>
#include <utility>
#include <vector>

namespace wash::tr {

class ProgramIndex {
public:
  /// Function bodies all walks of one translation may enter together.
  static constexpr unsigned DefaultBudget = 200000;

  explicit ProgramIndex(clang::ASTContext &Ctx, unsigned Budget = DefaultBudget);

  clang::ASTContext &context() const { return Ctx; }

  /// The user wrote FD (its definition, if it has one): it is not in a system
  /// header (the standard library, the wash API, passed with -isystem).
  bool isUserFunction(const clang::FunctionDecl *FD) const;

  /// The definition of main, or nullptr.
  const clang::FunctionDecl *main() const { return Main; }

  /// The direct calls of F, template instantiations included.
  const std::vector<const clang::CallExpr *> &callsOf(const clang::FunctionDecl *F) const;
  /// The functions a free function F calls directly from its own body (not
  /// from lambdas in it).
  const std::set<const clang::FunctionDecl *> &calleesOf(const clang::FunctionDecl *F) const;
  /// Functions that may run other than by a call from a free function's
  /// body: called from a member function, a lambda or an initialiser,
  /// named other than as a callee or an argument of a wash API call, or
  /// named through an overload set resolved later.
  const std::set<const clang::FunctionDecl *> &runAnywhere() const { return Anywhere; }
  /// Roots and every function they reach through calleesOf.
  std::set<const clang::FunctionDecl *>
  reachableFrom(const std::vector<const clang::FunctionDecl *> &Roots) const;

  /// Takes one step of the shared budget: false once it is spent.
  bool spend();
  bool spent() const { return Left == 0; }
  /// The budget the index started with.
  unsigned budget() const { return Total; }
  /// True the first time only: a spent budget is reported once, by the
  /// first walk it stops.
  bool firstOverrun() { return !std::exchange(Overrun, true); }
  /// A walk ran out of budget (and said so through firstOverrun).
  bool overran() const { return Overrun; }

private:
  friend class CallIndexer;
  clang::ASTContext &Ctx;
  const clang::FunctionDecl *Main = nullptr;
  std::map<const clang::FunctionDecl *, std::vector<const clang::CallExpr *>> Calls;
  std::map<const clang::FunctionDecl *, std::set<const clang::FunctionDecl *>> Callees;
  std::set<const clang::FunctionDecl *> Anywhere;
  unsigned Total, Left;
  bool Overrun = false;
};

/// A walk that follows calls into bodies, with what the walker keeps for
/// each function being walked (Frame).
template <typename Frame = bool> class CallWalk {
public:
  enum class Entry { Entered, Recursive, OverBudget };

  explicit CallWalk(ProgramIndex &Index) : Index(Index) {}

  /// Starts walking FD: Recursive when FD is already being walked (nothing
  /// pushed), OverBudget when the program's budget is spent.
  Entry push(const clang::FunctionDecl *FD, Frame F = {}) {
    if (find(FD))
      return Entry::Recursive;
    if (!Index.spend())
      return Entry::OverBudget;
    Stack.push_back({FD->getCanonicalDecl(), F});
    return Entry::Entered;
  }
  void pop() { Stack.pop_back(); }

  /// Walks FD with Body() between push and pop.
  template <typename Fn> Entry enter(const clang::FunctionDecl *FD, Fn &&Body, Frame F = {}) {
    Entry E = push(FD, F);
    if (E == Entry::Entered) {
      Body();
      pop();
    }
    return E;
  }

  /// The frame of FD if it is being walked.
  const Frame *find(const clang::FunctionDecl *FD) const {
    const clang::FunctionDecl *Canon = FD->getCanonicalDecl();
    for (auto It = Stack.rbegin(); It != Stack.rend(); ++It)
      if (It->first == Canon)
        return &It->second;
    return nullptr;
  }
  bool empty() const { return Stack.empty(); }

private:
  ProgramIndex &Index;
  std::vector<std::pair<const clang::FunctionDecl *, Frame>> Stack;
};

} // namespace wash::tr
