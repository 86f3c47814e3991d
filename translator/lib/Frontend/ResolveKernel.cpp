//===- ResolveKernel.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/ResolveKernel.h"

#include "clang/AST/ExprCXX.h"

using namespace clang;

namespace wash::tr {

/// The function named under casts, & and parentheses; casts are looked
/// through so that the signature check below sees the real function.
static const FunctionDecl *namedFunction(const Expr *E) {
  while (true) {
    E = E->IgnoreParens();
    if (const auto *C = dyn_cast<CastExpr>(E))
      E = C->getSubExpr();
    else if (const auto *U = dyn_cast<UnaryOperator>(E); U && U->getOpcode() == UO_AddrOf)
      E = U->getSubExpr();
    else
      break;
  }
  const auto *DRE = dyn_cast<DeclRefExpr>(E);
  return DRE ? dyn_cast<FunctionDecl>(DRE->getDecl()) : nullptr;
}

const FunctionDecl *resolveKernel(const CallExpr *Registration, KernelKind Kind, ASTContext &Ctx,
                                  Diagnoser &D) {
  if (Registration->getNumArgs() < 1)
    return nullptr;
  const Expr *Arg = Registration->getArg(0);
  const FunctionDecl *FD = namedFunction(Arg);
  if (!FD || isa<CXXMethodDecl>(FD)) {
    D.report(DiagId::KernelNotFunction, Arg->getExprLoc());
    return nullptr;
  }
  std::string Name = FD->getQualifiedNameAsString();

  // The expected type comes from the API itself: add_force_kernel(ForceKernel).
  const FunctionDecl *Callee = Registration->getDirectCallee();
  QualType Expected = Callee->getParamDecl(0)->getType()->getPointeeType();
  if (Expected.isNull() || !Ctx.hasSameType(FD->getType(), Expected)) {
    PrintingPolicy PP(Ctx.getLangOpts());
    D.report(DiagId::KernelWrongSignature, Arg->getExprLoc(),
             {kernelKindName(Kind), Name, FD->getType().getCanonicalType().getAsString(PP),
              Expected.isNull() ? "?" : Expected.getCanonicalType().getAsString(PP)});
    D.report(DiagId::NoteDeclaredHere, FD->getLocation(), {Name});
    return nullptr;
  }

  const FunctionDecl *Def = FD->getDefinition();
  if (!Def || !Def->hasBody()) {
    D.report(DiagId::KernelNotDefined, Arg->getExprLoc(), {Name});
    D.report(DiagId::NoteDeclaredHere, FD->getLocation(), {Name});
    return nullptr;
  }
  return Def;
}

} // namespace wash::tr
