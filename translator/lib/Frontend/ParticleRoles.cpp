//===- ParticleRoles.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/ParticleRoles.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ExprCXX.h"

using namespace clang;

namespace wash::tr {

Roles RoleEvaluator::of(const Expr *E) const {
  PeelOptions Through;
  Through.ExplicitCasts = true; // const_cast, C casts, decay...
  // A copy of a particle is a handle to the same particle.
  Through.IsCopy = [](const CXXConstructExpr *CE) {
    return CE->getNumArgs() == 1 && involvesParticle(CE->getType());
  };
  E = E ? peel(E, Through) : nullptr;
  if (isa_and_nonnull<CXXConstructExpr>(E))
    return 0;
  if (!E)
    return 0;
  if (const auto *DRE = dyn_cast<DeclRefExpr>(E))
    return Vars(DRE->getDecl());
  if (const auto *U = dyn_cast<UnaryOperator>(E)) {
    if (U->getOpcode() == UO_Deref)
      return derefRoles(of(U->getSubExpr()));
    if (U->getOpcode() == UO_AddrOf || U->isIncrementDecrementOp())
      return of(U->getSubExpr());
    return 0;
  }
  if (const auto *B = dyn_cast<BinaryOperator>(E)) {
    if (B->isAssignmentOp())
      return of(B->getLHS());
    if (B->getOpcode() == BO_Comma)
      return of(B->getRHS());
    if (B->isAdditiveOp() && B->getType()->isPointerType())
      return of(B->getLHS()) | of(B->getRHS());
    return 0;
  }
  if (const auto *A = dyn_cast<ArraySubscriptExpr>(E))
    return derefRoles(of(A->getBase()));
  if (const auto *C = dyn_cast<AbstractConditionalOperator>(E))
    return of(C->getTrueExpr()) | of(C->getFalseExpr());
  if (const auto *CE = dyn_cast<CallExpr>(E)) {
    if (auto R = Calls(CE))
      return *R;
    return ofLibraryCall(CE);
  }
  return 0;
}

Roles RoleEvaluator::ofLibraryCall(const CallExpr *CE) const {
  const FunctionDecl *FD = CE->getDirectCallee();
  if (!FD)
    return 0;
  if (isWashCall(FD, ApiCall::create_particle))
    return RoleOwn;
  StringRef Name = FD->getIdentifier() ? FD->getName() : "";

  // vector::operator[], *it, it->, ++it, it + n, ...
  if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(CE)) {
    if (OC->getNumArgs() == 0)
      return 0;
    Roles R0 = of(OC->getArg(0));
    switch (OC->getOperator()) {
    case OO_Subscript:
    case OO_Star:
    case OO_Arrow:
      return R0 & (RoleList | RoleIter) ? RoleNeighbour : 0;
    case OO_PlusPlus:
    case OO_MinusMinus:
    case OO_PlusEqual:
    case OO_MinusEqual:
    case OO_Equal:
      return R0;
    case OO_Plus:
    case OO_Minus:
      return (R0 | (OC->getNumArgs() > 1 ? of(OC->getArg(1)) : 0)) & RoleIter;
    default:
      return 0;
    }
  }
  if (const auto *MC = dyn_cast<CXXMemberCallExpr>(CE)) {
    Roles R = of(MC->getImplicitObjectArgument());
    if (R & RoleList) {
      if (isOneOf(Name, {"at", "front", "back"}))
        return RoleNeighbour;
      if (isOneOf(Name, {"begin", "end", "cbegin", "cend", "rbegin", "rend", "crbegin", "crend",
                         "data", "base"}))
        return RoleIter;
    }
    if (R & RoleIter && Name == "base")
      return RoleIter;
    return 0;
  }
  // std::begin(v), std::next(it), std::data(v), ...
  if (CE->getNumArgs() >= 1 &&
      isOneOf(Name, {"begin", "end", "cbegin", "cend", "rbegin", "rend", "data", "next", "prev",
                     "addressof", "as_const", "move", "ref", "cref"})) {
    Roles R = of(CE->getArg(0));
    if (isOneOf(Name, {"addressof", "as_const", "move", "ref", "cref"}))
      return R;
    return R & (RoleList | RoleIter) ? RoleIter : 0;
  }
  return 0;
}

} // namespace wash::tr
