//===- GlobalWrites.cpp ---------------------------------------------------===//
#include "wash/translator/Frontend/GlobalWrites.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"

using namespace clang;

namespace wash::tr {
namespace {

/// The global or static variable E names, through members, subscripts,
/// dereferences and local references or pointers initialised to it.
const VarDecl *storageOf(const Expr *E) {
  for (unsigned Depth = 0; E && Depth < 64; ++Depth) {
    E = E->IgnoreParenImpCasts();
    if (const auto *M = dyn_cast<MemberExpr>(E)) {
      if (const auto *VD = dyn_cast<VarDecl>(M->getMemberDecl())) // Static member.
        return VD->hasGlobalStorage() ? VD : nullptr;
      E = M->isArrow() ? nullptr : M->getBase();
    } else if (const auto *A = dyn_cast<ArraySubscriptExpr>(E)) {
      E = A->getBase()->IgnoreParenImpCasts();
      if (!E->getType()->isArrayType())
        return nullptr; // Through a pointer: not this variable's storage.
    } else if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(E);
               OC && OC->getOperator() == OO_Subscript) {
      E = OC->getArg(0); // v[i] of a global container.
    } else if (const auto *U = dyn_cast<UnaryOperator>(E); U && U->getOpcode() == UO_Deref) {
      E = U->getSubExpr(); // *q: a global pointer, or a local one set to &g.
    } else if (const auto *DRE = dyn_cast<DeclRefExpr>(E)) {
      const auto *VD = dyn_cast<VarDecl>(DRE->getDecl());
      if (!VD || VD->hasGlobalStorage())
        return VD;
      // A local alias of a global: `double &r = g;`, `double *q = &g;`. Only
      // its initialiser is followed, not later assignments to a pointer.
      const Expr *Init = VD->getInit();
      if (!Init || !(VD->getType()->isReferenceType() || VD->getType()->isPointerType()))
        return nullptr;
      E = Init->IgnoreParenImpCasts();
      if (const auto *A = dyn_cast<UnaryOperator>(E); A && A->getOpcode() == UO_AddrOf)
        E = A->getSubExpr();
      else if (VD->getType()->isPointerType() && !E->getType()->isArrayType() &&
               !E->getType()->isPointerType())
        return nullptr;
    } else {
      return nullptr;
    }
  }
  return nullptr;
}

} // namespace

const VarDecl *globalWrittenBy(const Stmt *S) {
  const Expr *Target = nullptr;
  if (const auto *B = dyn_cast<BinaryOperator>(S); B && B->isAssignmentOp())
    Target = B->getLHS();
  else if (const auto *U = dyn_cast<UnaryOperator>(S); U && U->isIncrementDecrementOp())
    Target = U->getSubExpr();
  else if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(S);
           OC && OC->getNumArgs() > 0 && isa_and_nonnull<CXXMethodDecl>(OC->getDirectCallee()) &&
           !cast<CXXMethodDecl>(OC->getDirectCallee())->isConst())
    Target = OC->getArg(0); // g += x, ++g, g(x) on a class type.
  else if (const auto *MC = dyn_cast<CXXMemberCallExpr>(S); MC && MC->getMethodDecl() &&
                                                            !MC->getMethodDecl()->isConst() &&
                                                            !MC->getMethodDecl()->isStatic())
    Target = MC->getImplicitObjectArgument(); // rng(), v.push_back(x)...
  if (!Target)
    return nullptr;
  return storageOf(Target);
}

} // namespace wash::tr
