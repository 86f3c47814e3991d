//===- ProgramIndex.cpp ---------------------------------------------------===//
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ParentMapContext.h"
#include "clang/AST/RecursiveASTVisitor.h"

using namespace clang;

namespace wash::tr {

static const FunctionDecl *canonical(const FunctionDecl *FD) {
  return FD ? FD->getCanonicalDecl() : nullptr;
}

/// Records every call with the free function it is made from (none from a
/// member, a lambda or an initialiser: those may run anywhere).
class CallIndexer : public RecursiveASTVisitor<CallIndexer> {
public:
  explicit CallIndexer(ProgramIndex &Index) : Index(Index) {}

  bool shouldVisitTemplateInstantiations() const { return true; }
  bool shouldVisitImplicitCode() const { return true; }

  bool TraverseFunctionDecl(FunctionDecl *FD) {
    if (FD->isMain() && FD->isThisDeclarationADefinition() && !Index.Main)
      Index.Main = FD;
    return inside(canonical(FD), [&] { return RecursiveASTVisitor::TraverseFunctionDecl(FD); });
  }
  bool TraverseCXXMethodDecl(CXXMethodDecl *FD) {
    return inside(nullptr, [&] { return RecursiveASTVisitor::TraverseCXXMethodDecl(FD); });
  }
  bool TraverseLambdaExpr(LambdaExpr *L) {
    return inside(nullptr, [&] { return RecursiveASTVisitor::TraverseLambdaExpr(L); });
  }

  bool VisitCallExpr(CallExpr *E) {
    const FunctionDecl *Callee = canonical(E->getDirectCallee());
    if (!Callee)
      return true;
    CalleeRefs.insert(E->getCallee()->IgnoreParenImpCasts());
    const FunctionDecl *Caller = Stack.empty() ? nullptr : Stack.back();
    if (Caller)
      Index.Callees[Caller].insert(Callee);
    else
      Index.Anywhere.insert(Callee);
    Index.Calls[Callee].push_back(E);
    return true;
  }

  bool VisitDeclRefExpr(DeclRefExpr *E) {
    if (isa<FunctionDecl>(E->getDecl()))
      FunctionRefs.push_back(E);
    return true;
  }

  bool VisitOverloadExpr(OverloadExpr *E) { // names resolved only later
    for (const NamedDecl *ND : E->decls())
      if (const auto *FD = dyn_cast<FunctionDecl>(ND->getUnderlyingDecl()))
        Index.Anywhere.insert(canonical(FD));
    return true;
  }

  /// Functions named other than as a callee: their address may be called anywhere.
  void finish() {
    for (const DeclRefExpr *Ref : FunctionRefs)
      if (!CalleeRefs.count(Ref) && !inRegistration(Ref))
        Index.Anywhere.insert(canonical(cast<FunctionDecl>(Ref->getDecl())));
  }

private:
  template <typename Fn> bool inside(const FunctionDecl *F, Fn Traverse) {
    Stack.push_back(F);
    bool Result = Traverse();
    Stack.pop_back();
    return Result;
  }

  /// A kernel's function named in the call that registers it.
  bool inRegistration(const Expr *Ref) const {
    const Expr *E = Ref;
    for (unsigned Up = 0; Up < 6; ++Up) {
      auto Parents = Index.Ctx.getParents(*E);
      if (Parents.size() != 1)
        return false;
      if (const auto *Call = Parents[0].get<CallExpr>())
        return isWashFunction(Call->getDirectCallee());
      const auto *Next = Parents[0].get<Expr>();
      if (!Next ||
          !(isa<ImplicitCastExpr>(Next) || isa<ParenExpr>(Next) || isa<UnaryOperator>(Next)))
        return false;
      E = Next;
    }
    return false;
  }

  ProgramIndex &Index;
  std::vector<const FunctionDecl *> Stack;
  std::set<const Expr *> CalleeRefs;
  std::vector<const DeclRefExpr *> FunctionRefs;
};

ProgramIndex::ProgramIndex(ASTContext &Ctx, unsigned Budget)
    : Ctx(Ctx), Total(Budget), Left(Budget) {
  CallIndexer Indexer(*this);
  Indexer.TraverseDecl(Ctx.getTranslationUnitDecl());
  Indexer.finish();
}

bool ProgramIndex::isUserFunction(const FunctionDecl *FD) const {
  if (!FD)
    return false;
  const FunctionDecl *Def = FD->getDefinition();
  return isUserCode(Ctx.getSourceManager(), Def ? Def : FD);
}

const std::vector<const CallExpr *> &ProgramIndex::callsOf(const FunctionDecl *F) const {
  static const std::vector<const CallExpr *> None;
  auto It = Calls.find(canonical(F));
  return It == Calls.end() ? None : It->second;
}

const std::set<const FunctionDecl *> &ProgramIndex::calleesOf(const FunctionDecl *F) const {
  static const std::set<const FunctionDecl *> None;
  auto It = Callees.find(canonical(F));
  return It == Callees.end() ? None : It->second;
}

std::set<const FunctionDecl *>
ProgramIndex::reachableFrom(const std::vector<const FunctionDecl *> &Roots) const {
  std::set<const FunctionDecl *> Seen;
  std::vector<const FunctionDecl *> Work;
  for (const FunctionDecl *R : Roots)
    if (R && Seen.insert(canonical(R)).second)
      Work.push_back(canonical(R));
  while (!Work.empty()) {
    const FunctionDecl *F = Work.back();
    Work.pop_back();
    for (const FunctionDecl *C : calleesOf(F))
      if (Seen.insert(C).second)
        Work.push_back(C);
  }
  return Seen;
}

bool ProgramIndex::spend() {
  if (Left == 0)
    return false;
  --Left;
  return true;
}

} // namespace wash::tr
