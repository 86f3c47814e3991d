//===- ParameterBindings.cpp ----------------------------------------------===//
#include "wash/translator/Frontend/ParameterBindings.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"
#include "clang/AST/RecursiveASTVisitor.h"

#include <map>
#include <memory>
#include <set>

using namespace clang;

namespace wash::tr {

const Expr *argumentFor(const CallExpr *Call, const FunctionDecl *Callee, const ParmVarDecl *P) {
  if (!Call || !Callee || !P)
    return nullptr;
  const auto *Owner = dyn_cast<FunctionDecl>(P->getDeclContext());
  if (!Owner || Owner->getCanonicalDecl() != Callee->getCanonicalDecl())
    return nullptr;
  unsigned Index = P->getFunctionScopeIndex();
  // `f(a, b)` on a closure or class: argument 0 is the object.
  if (const auto *Op = dyn_cast<CXXOperatorCallExpr>(Call);
      Op && isa<CXXMethodDecl>(Callee) && !cast<CXXMethodDecl>(Callee)->isStatic())
    ++Index;
  return Index < Call->getNumArgs() ? Call->getArg(Index) : nullptr;
}

namespace {

/// The calls of every free function, and the functions named other than by a
/// direct call, over the whole translation unit.
class CallIndex : public RecursiveASTVisitor<CallIndex> {
public:
  bool shouldVisitTemplateInstantiations() const { return true; }
  bool shouldVisitImplicitCode() const { return true; }

  bool VisitCallExpr(CallExpr *CE) {
    if (const FunctionDecl *FD = CE->getDirectCallee()) {
      Calls[FD->getCanonicalDecl()].push_back(CE);
      if (const auto *DRE = dyn_cast<DeclRefExpr>(CE->getCallee()->IgnoreParenImpCasts()))
        Callees.insert(DRE);
    }
    return true;
  }

  bool VisitDeclRefExpr(DeclRefExpr *DRE) {
    if (const auto *FD = dyn_cast<FunctionDecl>(DRE->getDecl()))
      Named.push_back({FD->getCanonicalDecl(), DRE});
    return true;
  }

  /// After the traversal: the functions named other than as a callee.
  std::set<const FunctionDecl *> escaped() const {
    std::set<const FunctionDecl *> Out;
    for (const auto &[FD, DRE] : Named)
      if (!Callees.count(DRE))
        Out.insert(FD);
    return Out;
  }

  std::map<const FunctionDecl *, std::vector<const CallExpr *>> Calls;

private:
  std::set<const DeclRefExpr *> Callees;
  std::vector<std::pair<const FunctionDecl *, const DeclRefExpr *>> Named;
};

struct ProgramCalls {
  const ASTContext *Ctx = nullptr;
  std::map<const FunctionDecl *, std::vector<const CallExpr *>> Calls;
  std::set<const FunctionDecl *> Escaped;
};

const ProgramCalls &programCalls(ASTContext &Ctx) {
  // One translation unit per run; rebuilt if another context asks.
  static std::unique_ptr<ProgramCalls> Cached;
  if (!Cached || Cached->Ctx != &Ctx) {
    CallIndex Index;
    Index.TraverseAST(Ctx);
    Cached = std::make_unique<ProgramCalls>();
    Cached->Ctx = &Ctx;
    Cached->Calls = std::move(Index.Calls);
    Cached->Escaped = Index.escaped();
  }
  return *Cached;
}

} // namespace

const std::vector<const CallExpr *> &visibleCalls(const ParmVarDecl *P, ASTContext &Ctx) {
  static const std::vector<const CallExpr *> None;
  const auto *FD = P ? dyn_cast<FunctionDecl>(P->getDeclContext()) : nullptr;
  if (!FD || isa<CXXMethodDecl>(FD) || FD->isTemplated() || FD->isTemplateInstantiation() ||
      FD->isMain())
    return None;
  const ProgramCalls &Program = programCalls(Ctx);
  if (Program.Escaped.count(FD->getCanonicalDecl()))
    return None;
  auto It = Program.Calls.find(FD->getCanonicalDecl());
  return It == Program.Calls.end() ? None : It->second;
}

} // namespace wash::tr
