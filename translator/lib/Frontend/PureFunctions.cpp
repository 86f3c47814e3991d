//===- PureFunctions.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/PureFunctions.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"
#include "clang/AST/RecursiveASTVisitor.h"

#include <set>
#include <string>

using namespace clang;

namespace wash::tr {

bool isArithmetic(QualType T) {
  return !T.isNull() && T.getNonReferenceType()->isArithmeticType() &&
         !T.getNonReferenceType()->isEnumeralType();
}

/// <cmath> functions without side effects that matter to a value.
bool isMathFunction(const FunctionDecl *FD, const SourceManager &SM) {
  static const std::set<std::string> Names = {
      "sqrt",  "cbrt", "pow",  "exp",      "exp2",  "expm1", "log",  "log2",  "log10",
      "log1p", "fabs", "abs",  "sin",      "cos",   "tan",   "asin", "acos",  "atan",
      "atan2", "sinh", "cosh", "tanh",     "hypot", "floor", "ceil", "trunc", "round",
      "fmin",  "fmax", "fma",  "copysign", "min",   "max"};
  if (!FD->getIdentifier() || !Names.count(FD->getName().str()) || isUserCode(SM, FD))
    return false;
  const DeclContext *DC = FD->getDeclContext()->getRedeclContext();
  if (DC->isTranslationUnit())
    return true;
  const auto *NS = dyn_cast<NamespaceDecl>(DC);
  return NS && NS->getName() == "std" && NS->getParent()->getRedeclContext()->isTranslationUnit();
}

bool Purity::pure(const FunctionDecl *FD) {
  if (!FD)
    return false;
  if (isMathFunction(FD, SM))
    return true;
  FD = FD->getDefinition();
  if (!FD || isa<CXXMethodDecl>(FD) || FD->isVariadic() || isWashFunction(FD) ||
      !isUserCode(SM, FD))
    return false;
  auto [It, New] = Known.try_emplace(FD, false); // false while in progress: no recursion
  if (!New)
    return It->second;
  bool Result = isArithmetic(FD->getReturnType()) && !FD->getReturnType()->isReferenceType();
  for (const ParmVarDecl *P : FD->parameters())
    Result = Result && parameterReadOnly(P->getType());
  Result = Result && stmt(FD->getBody(), FD);
  Known[FD] = Result;
  return Result;
}

bool Purity::parameterReadOnly(QualType T) {
  return !T->isReferenceType() || T.getNonReferenceType().isConstQualified();
}

bool Purity::stmt(const Stmt *S, const FunctionDecl *F) {
  if (!S)
    return true;
  if (isa<CompoundStmt, ReturnStmt, IfStmt, NullStmt, ParenExpr, ConditionalOperator,
          IntegerLiteral, FloatingLiteral, CXXBoolLiteralExpr, MaterializeTemporaryExpr,
          ConstantExpr, ExprWithCleanups>(S)) {
    // fall through to the children
  } else if (const auto *DS = dyn_cast<DeclStmt>(S)) {
    for (const Decl *D : DS->decls()) {
      const auto *V = dyn_cast<VarDecl>(D);
      if (!V || !V->hasLocalStorage() || V->getType()->isReferenceType() ||
          !isArithmetic(V->getType()))
        return false;
    }
  } else if (const auto *Cast = dyn_cast<CastExpr>(S)) {
    if (Cast->getCastKind() == CK_FloatingToIntegral || !castable(Cast))
      return false;
  } else if (const auto *Bin = dyn_cast<BinaryOperator>(S)) {
    if (!binaryAllowed(Bin) || (Bin->isAssignmentOp() && !writesLocal(Bin->getLHS(), F)))
      return false;
  } else if (const auto *Un = dyn_cast<UnaryOperator>(S)) {
    if (Un->getOpcode() == UO_AddrOf || Un->getOpcode() == UO_Deref ||
        (Un->isIncrementDecrementOp() && !writesLocal(Un->getSubExpr(), F)))
      return false;
  } else if (const auto *Ref = dyn_cast<DeclRefExpr>(S)) {
    if (!readable(Ref->getDecl(), F))
      return false;
  } else if (const auto *Member = dyn_cast<MemberExpr>(S)) {
    const auto *Field = dyn_cast<FieldDecl>(Member->getMemberDecl());
    if (Member->isArrow() || !Field || Field->isMutable())
      return false;
  } else if (const auto *Call = dyn_cast<CallExpr>(S)) {
    if (isa<CXXMemberCallExpr, CXXOperatorCallExpr>(Call) || !pure(Call->getDirectCallee()))
      return false;
    for (const Expr *Arg : Call->arguments()) // the callee is pure: skip its name
      if (!stmt(Arg, F))
        return false;
    return true;
  } else {
    return false; // loops, throw, new, asm, lambdas, member calls, ...
  }
  for (const Stmt *Child : S->children())
    if (!stmt(Child, F))
      return false;
  return true;
}

bool Purity::castable(const CastExpr *Cast) {
  switch (Cast->getCastKind()) {
  case CK_LValueToRValue:
  case CK_NoOp:
  case CK_IntegralCast:
  case CK_IntegralToFloating:
  case CK_FloatingCast:
  case CK_IntegralToBoolean:
  case CK_FloatingToBoolean:
  case CK_FunctionToPointerDecay:
    return true;
  default:
    return false;
  }
}

bool Purity::readable(const ValueDecl *D, const FunctionDecl *F) const {
  if (isa<EnumConstantDecl>(D) || isa<FunctionDecl>(D))
    return true;
  const auto *V = dyn_cast<VarDecl>(D);
  if (!V)
    return false;
  if (V->hasLocalStorage()) // its own parameters and locals
    return V->getDeclContext() == F;
  QualType T = V->getType();
  return V->isFileVarDecl() && T.isConstQualified() && !T.isVolatileQualified() &&
         !T->isReferenceType();
}

bool Purity::writesLocal(const Expr *E, const FunctionDecl *F) {
  const auto *Ref = dyn_cast<DeclRefExpr>(E->IgnoreParens());
  const auto *V = Ref ? dyn_cast<VarDecl>(Ref->getDecl()) : nullptr;
  return V && V->hasLocalStorage() && V->getDeclContext() == F && !V->getType()->isReferenceType();
}

bool Purity::binaryAllowed(const BinaryOperator *Bin) {
  BinaryOperatorKind Op = Bin->getOpcode();
  if (Op == BO_Comma || Bin->isShiftOp() || Bin->isShiftAssignOp() || Op == BO_PtrMemD ||
      Op == BO_PtrMemI)
    return false;
  if ((Op == BO_Div || Op == BO_Rem || Op == BO_DivAssign || Op == BO_RemAssign) &&
      !Bin->getType()->isRealFloatingType() &&
      !(Bin->isCompoundAssignmentOp() &&
        cast<CompoundAssignOperator>(Bin)->getComputationResultType()->isRealFloatingType()))
    return false;
  return isArithmetic(Bin->getLHS()->getType()) && isArithmetic(Bin->getRHS()->getType());
}

} // namespace wash::tr
