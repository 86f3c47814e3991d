//===- AstQueries.cpp -----------------------------------------------------===//
#include "wash/translator/Frontend/AstQueries.h"

#include "clang/AST/DeclCXX.h"

#include <vector>

using namespace clang;

namespace wash::tr {

static const Expr *peelOnce(const Expr *E, const PeelOptions &O) {
  if (const auto *P = dyn_cast<ParenExpr>(E))
    return P->getSubExpr();
  if (const auto *C = dyn_cast<ImplicitCastExpr>(E))
    return C->getSubExpr();
  if (const auto *C = dyn_cast<ExplicitCastExpr>(E);
      C && (O.ExplicitCasts || (O.FunctionalCasts && isa<CXXFunctionalCastExpr>(C))))
    return C->getSubExpr();
  if (const auto *M = dyn_cast<MaterializeTemporaryExpr>(E))
    return M->getSubExpr();
  if (const auto *B = dyn_cast<CXXBindTemporaryExpr>(E))
    return B->getSubExpr();
  if (const auto *F = dyn_cast<FullExpr>(E))
    return F->getSubExpr();
  if (const auto *D = dyn_cast<CXXDefaultArgExpr>(E); D && O.DefaultArguments)
    return D->getExpr();
  if (const auto *L = dyn_cast<CXXStdInitializerListExpr>(E); L && O.InitializerLists)
    return L->getSubExpr();
  if (const auto *S = dyn_cast<SubstNonTypeTemplateParmExpr>(E))
    return S->getReplacement();
  if (const auto *C = dyn_cast<CXXConstructExpr>(E)) {
    bool Copy = O.IsCopy ? O.IsCopy(C)
                         : C->getNumArgs() == 1 && C->getConstructor()->isCopyOrMoveConstructor();
    return Copy ? C->getArg(0) : E;
  }
  if (const auto *DRE = dyn_cast<DeclRefExpr>(E); DRE && O.VariableInitialisers)
    if (const auto *VD = dyn_cast<VarDecl>(DRE->getDecl()); VD && VD->getInit())
      return VD->getInit();
  return E;
}

const Expr *peel(const Expr *E, const PeelOptions &Options) {
  // Bounded: a variable initialised with itself would otherwise loop.
  for (unsigned Step = 0; E && Step < 256; ++Step) {
    const Expr *Next = peelOnce(E, Options);
    if (Next == E)
      return E;
    E = Next;
  }
  return E;
}

bool constructsFromOneArgument(const CXXConstructExpr *CE) { return CE->getNumArgs() == 1; }

bool noConstruction(const CXXConstructExpr *) { return false; }

namespace {
/// A node of the body and where its parent is in the walk's list.
struct Visited {
  const Stmt *S;
  int Parent;
};
} // namespace

/// Whether the use Nodes[At] (a DeclRefExpr) only reads the variable.
static bool readAt(const std::vector<Visited> &Nodes, int At) {
  const Stmt *Use = Nodes[At].S;
  for (int Up = Nodes[At].Parent; Up >= 0; Use = Nodes[Up].S, Up = Nodes[Up].Parent) {
    const Stmt *Parent = Nodes[Up].S;
    if (isa<ParenExpr>(Parent))
      continue;
    if (const auto *Cast = dyn_cast<ImplicitCastExpr>(Parent)) {
      if (Cast->getCastKind() == CK_LValueToRValue)
        return true;
      if (Cast->getCastKind() == CK_NoOp)
        continue;
      return false;
    }
    if (const auto *Member = dyn_cast<MemberExpr>(Parent)) {
      const auto *Method = dyn_cast<CXXMethodDecl>(Member->getMemberDecl());
      return Member->getBase() == Use && Method && Method->isConst();
    }
    const FunctionDecl *Callee = nullptr;
    llvm::ArrayRef<const Expr *> Args;
    if (const auto *Construct = dyn_cast<CXXConstructExpr>(Parent)) {
      Callee = Construct->getConstructor();
      Args = llvm::ArrayRef(Construct->getArgs(), Construct->getNumArgs());
    } else if (const auto *Call = dyn_cast<CallExpr>(Parent)) {
      Callee = Call->getDirectCallee();
      Args = llvm::ArrayRef(Call->getArgs(), Call->getNumArgs());
      if (isa<CXXOperatorCallExpr>(Call) && isa_and_nonnull<CXXMethodDecl>(Callee)) {
        if (!Args.empty() && Args[0] == Use) // the object of an operator
          return cast<CXXMethodDecl>(Callee)->isConst();
        Args = Args.drop_front();
      }
    }
    if (!Callee)
      return false;
    // Bound to a parameter that cannot change it: a copy or a const reference.
    for (unsigned I = 0; I < Args.size(); ++I)
      if (Args[I] == Use) {
        if (I >= Callee->getNumParams())
          return false;
        QualType T = Callee->getParamDecl(I)->getType();
        return !T->isReferenceType() || T.getNonReferenceType().isConstQualified();
      }
    return false;
  }
  return false;
}

bool onlyRead(const ValueDecl *V, const Stmt *Body) {
  if (!Body)
    return false;
  // Iterative, with parent links: a deeply nested body cannot overflow the stack.
  std::vector<Visited> Nodes{{Body, -1}};
  std::vector<int> Work{0};
  while (!Work.empty()) {
    int At = Work.back();
    Work.pop_back();
    const Stmt *S = Nodes[At].S;
    if (const auto *DRE = dyn_cast<DeclRefExpr>(S); DRE && DRE->getDecl() == V) {
      if (!readAt(Nodes, At))
        return false;
      continue;
    }
    for (const Stmt *Child : S->children())
      if (Child) {
        Nodes.push_back({Child, At});
        Work.push_back(Nodes.size() - 1);
      }
  }
  return true;
}

} // namespace wash::tr
