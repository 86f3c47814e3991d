//===- GlobalWrites.h - shared state a per-particle kernel changes -*- C++ -*-===//
//
// For InferAccesses: a per-particle kernel (update, force, reduction, and the
// helpers they reach) that changes a global or static variable, or library
// state, runs once per particle in an order that differs between backends and
// ranks, so its result differs from the reference. The analysis errs towards
// rejecting: whatever may designate or point into global storage and reaches
// a write, a non-const parameter of code it does not follow, or a helper
// parameter the helper writes through, is reported. Reading is fine.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/Stmt.h"

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace wash::tr {

/// Storage an expression may reach: a variable's own (Through false), or
/// what it refers or points to (Through true: a reference or pointer
/// parameter's argument, a global pointer's target).
struct StorageRoot {
  const clang::VarDecl *Var;
  bool Through;
  bool operator<(const StorageRoot &O) const {
    return Var != O.Var ? Var < O.Var : Through < O.Through;
  }
};
using StorageRoots = std::set<StorageRoot>;

/// Finds the shared state one kernel's walk changes, statement by statement.
class SharedStateFinder {
public:
  SharedStateFinder(clang::ASTContext &Ctx, Diagnoser &D, std::string KernelKind,
                    std::string Kernel)
      : Ctx(Ctx), D(D), KernelKind(std::move(KernelKind)), Kernel(std::move(Kernel)) {}

  /// Reports what S changes. The bodies of the user functions S calls must
  /// have been visited first, so that the parameters they write through are
  /// known.
  void visit(const clang::Stmt *S);

private:
  StorageRoots objectRoots(const clang::Expr *E, unsigned Depth = 0);
  StorageRoots pointeeRoots(const clang::Expr *E, unsigned Depth = 0);
  StorageRoots objectRootsOf(const clang::Expr *E, unsigned Depth);
  StorageRoots pointeeRootsOf(const clang::Expr *E, unsigned Depth);
  StorageRoots loadRoots(const clang::Expr *E, unsigned Depth);
  StorageRoots callRoots(const clang::Expr *Call, unsigned Depth);
  StorageRoots argumentRoots(const clang::Expr *Arg, clang::QualType Param, unsigned Depth);
  const StorageRoots &aliasesOf(const clang::VarDecl *Local);
  void scanFunction(const clang::FunctionDecl *FD);
  /// Callee: the function the roots were passed to; none for a write.
  void written(const StorageRoots &Roots, const clang::Stmt *At, std::optional<std::string> Callee);
  void call(const clang::Expr *Call, const clang::FunctionDecl *FD,
            llvm::ArrayRef<const clang::Expr *> Args, llvm::ArrayRef<clang::QualType> Params);
  bool followed(const clang::FunctionDecl *FD) const;
  void walk(const clang::FunctionDecl *FD);
  void writtenTarget(const clang::Expr *Target, const clang::Stmt *At);
  StorageRoots heldRoots(const clang::Expr *Object);
  bool writesThroughHeld(const clang::CXXRecordDecl *RD) const;
  bool writesThroughCallable(llvm::ArrayRef<const clang::Expr *> Args) const;

  clang::ASTContext &Ctx;
  Diagnoser &D;
  std::string KernelKind, Kernel;
  /// Reference and pointer parameters written through, by the helpers seen.
  std::set<const clang::ParmVarDecl *> WrittenParams;
  /// What each local pointer, iterator or aggregate may point into.
  std::map<const clang::VarDecl *, StorageRoots> Aliases;
  /// Globals (and parameters) each user function may return a reference or
  /// pointer into.
  std::map<const clang::FunctionDecl *, StorageRoots> Returns;
  std::set<const clang::FunctionDecl *> Scanned;
  /// Classes some member of which writes through a reference or pointer
  /// the object holds.
  std::set<const clang::CXXRecordDecl *> WritesThroughHeld;
  /// Roots already computed (object: false, pointee: true), for one visit.
  std::map<std::pair<const clang::Expr *, bool>, StorageRoots> Cache;
  /// Constructors and destructors (and what they call) walked here.
  std::set<const clang::FunctionDecl *> Walked;
};

/// The kernel opts out of the shared-state errors: its body calls
/// wash::allow_shared_state().
bool allowsSharedState(const clang::FunctionDecl *Kernel);

} // namespace wash::tr
