//===- WashApi.cpp --------------------------------------------------------===//
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/ExprCXX.h"
#include "clang/Basic/SourceManager.h"
#include "clang/Lex/Lexer.h"

#include <charconv>

using namespace clang;

namespace wash::tr {

static bool inWashNamespace(const DeclContext *DC) {
  const auto *NS = dyn_cast_or_null<NamespaceDecl>(DC ? DC->getRedeclContext() : nullptr);
  return NS && NS->getName() == "wash" && NS->getParent()->getRedeclContext()->isTranslationUnit();
}

bool isWashFunction(const FunctionDecl *FD) {
  return FD && !isa<CXXMethodDecl>(FD) && FD->getIdentifier() &&
         inWashNamespace(FD->getDeclContext());
}

const ApiCallInfo *washCall(const FunctionDecl *FD) {
  return isWashFunction(FD) ? apiCall(std::string_view(FD->getName())) : nullptr;
}

bool isWashCall(const FunctionDecl *FD, ApiCall Id) {
  const ApiCallInfo *Call = washCall(FD);
  return Call && Call->Id == Id;
}

bool isRegistrationFunction(const FunctionDecl *FD) {
  const ApiCallInfo *Call = washCall(FD);
  return Call && Call->readFromMain();
}

static bool isParticleRecord(const CXXRecordDecl *RD) {
  return RD && RD->getIdentifier() && RD->getName() == "Particle" &&
         inWashNamespace(RD->getDeclContext());
}

bool isParticleMethod(const FunctionDecl *FD) {
  const auto *MD = dyn_cast_or_null<CXXMethodDecl>(FD);
  return MD && isParticleRecord(MD->getParent());
}

std::optional<ParticleAccessor> particleAccessor(const FunctionDecl *FD) {
  if (!isParticleMethod(FD) || !FD->getIdentifier())
    return std::nullopt;
  return decodeAccessor(std::string_view(FD->getName()));
}

bool involvesParticle(QualType T) {
  if (T.isNull())
    return false;
  T = T.getNonReferenceType().getCanonicalType();
  while (T->isPointerType() || T->isArrayType())
    T = T->isPointerType() ? T->getPointeeType() : QualType(T->getArrayElementTypeNoTypeQual(), 0);
  const auto *RD = T->getAsCXXRecordDecl();
  if (!RD)
    return false;
  if (isParticleRecord(RD))
    return true;
  // std::vector<wash::Particle> and the like: any template whose argument does.
  if (const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(RD))
    for (const TemplateArgument &A : Spec->getTemplateArgs().asArray())
      if (A.getKind() == TemplateArgument::Type && involvesParticle(A.getAsType()))
        return true;
  return false;
}

std::optional<unsigned> vecDimension(QualType T) {
  if (T.isNull())
    return std::nullopt;
  T = T.getNonReferenceType().getCanonicalType();
  const auto *Spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(T->getAsCXXRecordDecl());
  if (!Spec || Spec->getName() != "Vec" || !inWashNamespace(Spec->getDeclContext()))
    return std::nullopt;
  const TemplateArgumentList &Args = Spec->getTemplateArgs();
  if (Args.size() != 2 || Args[1].getKind() != TemplateArgument::Integral)
    return std::nullopt;
  return static_cast<unsigned>(Args[1].getAsIntegral().getZExtValue());
}

bool isUserCode(const SourceManager &SM, const Decl *D) {
  SourceLocation L = D->getLocation();
  return L.isValid() && !SM.isInSystemHeader(SM.getExpansionLoc(L));
}

/// A construction from its first argument alone, the rest defaulted (an
/// allocator): not std::string(s, n), which keeps n characters of s.
static bool convertsOneArgument(const CXXConstructExpr *CE) {
  if (CE->getNumArgs() == 0 || isa<CXXDefaultArgExpr>(CE->getArg(0)))
    return false;
  for (unsigned I = 1; I < CE->getNumArgs(); ++I)
    if (!isa<CXXDefaultArgExpr>(CE->getArg(I)))
      return false;
  return true;
}

static const Expr *stripStringWrappers(const Expr *E) {
  while (true) {
    E = E->IgnoreParenImpCasts();
    if (const auto *M = dyn_cast<MaterializeTemporaryExpr>(E))
      E = M->getSubExpr();
    else if (const auto *B = dyn_cast<CXXBindTemporaryExpr>(E))
      E = B->getSubExpr();
    else if (const auto *C = dyn_cast<ExprWithCleanups>(E))
      E = C->getSubExpr();
    else if (const auto *F = dyn_cast<CXXFunctionalCastExpr>(E))
      E = F->getSubExpr();
    else if (const auto *CE = dyn_cast<CXXConstructExpr>(E); CE && convertsOneArgument(CE))
      E = CE->getArg(0); // std::string(const char *) or a copy of a string.
    else
      return E;
  }
}

std::optional<std::string> evaluateString(const Expr *E, ASTContext &Ctx) {
  for (unsigned Depth = 0; E && Depth < 16; ++Depth) {
    E = stripStringWrappers(E);
    // A literal reaches a std::string as a const char *: up to its first NUL.
    if (const auto *S = dyn_cast<StringLiteral>(E); S && S->getCharByteWidth() == 1)
      return S->getBytes().substr(0, S->getBytes().find('\0')).str();
    if (isa<StringLiteral>(E))
      return std::nullopt;
    if (E->getType()->isPointerType() && !E->isValueDependent())
      if (auto S = E->tryEvaluateString(Ctx))
        return S;
    // A const variable whose initialiser is a constant string.
    const auto *DRE = dyn_cast<DeclRefExpr>(E);
    const auto *VD = DRE ? dyn_cast<VarDecl>(DRE->getDecl()) : nullptr;
    if (!VD || !VD->getType().isConstQualified() || !VD->getAnyInitializer())
      return std::nullopt;
    E = VD->getAnyInitializer();
  }
  return std::nullopt;
}

std::optional<long long> evaluateInt(const Expr *E, ASTContext &Ctx) {
  Expr::EvalResult R;
  if (E->isValueDependent() || !E->EvaluateAsInt(R, Ctx))
    return std::nullopt;
  return R.Val.getInt().getExtValue();
}

std::optional<std::string> evaluateNumber(const Expr *E, ASTContext &Ctx) {
  Expr::EvalResult R;
  if (E->isValueDependent() || !E->EvaluateAsRValue(R, Ctx))
    return std::nullopt;
  double V;
  if (R.Val.isFloat())
    V = R.Val.getFloat().convertToDouble();
  else if (R.Val.isInt())
    V = static_cast<double>(R.Val.getInt().getExtValue());
  else
    return std::nullopt;
  char Buf[64];
  auto Res = std::to_chars(Buf, Buf + sizeof(Buf), V);
  return std::string(Buf, Res.ptr);
}

std::string sourceText(const Expr *E, ASTContext &Ctx) {
  CharSourceRange R = CharSourceRange::getTokenRange(E->getSourceRange());
  return Lexer::getSourceText(R, Ctx.getSourceManager(), Ctx.getLangOpts()).str();
}

} // namespace wash::tr
