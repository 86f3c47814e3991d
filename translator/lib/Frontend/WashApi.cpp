//===- WashApi.cpp --------------------------------------------------------===//
#include "wash/translator/Frontend/WashApi.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/ParameterBindings.h"

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
  PeelOptions Through;
  Through.FunctionalCasts = true;
  Through.DefaultArguments = true;      // A default names no parameter: it needs no context.
  Through.IsCopy = convertsOneArgument; // std::string(const char *) or a copy of a string.
  return peel(E, Through);
}

/// Whether the body of P's function may change P: the value a caller binds
/// is then not the value a use reads.
static bool mayBeChanged(const ParmVarDecl *P) {
  if (P->getType().isConstQualified())
    return false;
  QualType T = P->getType();
  if (T->isReferenceType())
    return !T.getNonReferenceType().isConstQualified();
  const auto *FD = dyn_cast<FunctionDecl>(P->getDeclContext());
  const Stmt *Body = FD ? FD->getBody() : nullptr;
  if (!Body)
    return true;
  // Any use of P other than reading its value may change it.
  return !onlyRead(P, Body);
}

static std::optional<std::string> evaluateString(const Expr *E, ASTContext &Ctx,
                                                 const CallContext *Context, unsigned Depth);

/// The value every visible call binds P to.
static std::optional<std::string> soleValue(const ParmVarDecl *P, ASTContext &Ctx, unsigned Depth) {
  const std::vector<const CallExpr *> &Calls = visibleCalls(P, Ctx);
  std::optional<std::string> Value;
  for (const CallExpr *Call : Calls) {
    auto Bound =
        evaluateString(argumentFor(Call, Call->getDirectCallee(), P), Ctx, nullptr, Depth + 1);
    if (!Bound || (Value && *Value != *Bound))
      return std::nullopt;
    Value = Bound;
  }
  return Value;
}

static std::optional<std::string> evaluateString(const Expr *E, ASTContext &Ctx,
                                                 const CallContext *Context, unsigned Depth) {
  for (; E && Depth < 16; ++Depth) {
    E = stripStringWrappers(E);
    // A literal reaches a std::string as a const char *: up to its first NUL.
    if (const auto *S = dyn_cast<StringLiteral>(E); S && S->getCharByteWidth() == 1)
      return S->getBytes().substr(0, S->getBytes().find('\0')).str();
    if (isa<StringLiteral>(E))
      return std::nullopt;
    if (E->getType()->isPointerType() && !E->isValueDependent())
      if (auto S = E->tryEvaluateString(Ctx))
        return S;
    const auto *DRE = dyn_cast<DeclRefExpr>(E);
    const auto *VD = DRE ? dyn_cast<VarDecl>(DRE->getDecl()) : nullptr;
    // A parameter: what the call binds it to, never its default as such.
    if (const auto *P = dyn_cast_or_null<ParmVarDecl>(VD)) {
      if (mayBeChanged(P))
        return std::nullopt;
      const CallContext *C = Context;
      const Expr *Arg = nullptr;
      for (; C && !Arg; C = C->Outer)
        Arg = argumentFor(C->Call, C->Callee, P);
      if (!Arg)
        return Context ? std::nullopt : soleValue(P, Ctx, Depth);
      E = Arg;
      Context = C; // the caller's context: the link after the call's
      continue;
    }
    // A const variable whose initialiser is a constant string.
    if (!VD || !VD->getType().isConstQualified() || !VD->getAnyInitializer())
      return std::nullopt;
    E = VD->getAnyInitializer();
  }
  return std::nullopt;
}

std::optional<std::string> evaluateString(const Expr *E, ASTContext &Ctx,
                                          const CallContext *Context) {
  return evaluateString(E, Ctx, Context, 0);
}

/// E with the parameters Context binds replaced by their arguments.
static const Expr *bindArguments(const Expr *E, const CallContext *Context) {
  for (unsigned Depth = 0; E && Context && Depth < 16; ++Depth) {
    const Expr *Plain = E->IgnoreParenImpCasts();
    if (const auto *D = dyn_cast<CXXDefaultArgExpr>(Plain))
      return D->getExpr();
    const auto *DRE = dyn_cast<DeclRefExpr>(Plain);
    const auto *P = DRE ? dyn_cast<ParmVarDecl>(DRE->getDecl()) : nullptr;
    if (!P || mayBeChanged(P))
      return E;
    const Expr *Arg = nullptr;
    for (; Context && !Arg; Context = Context->Outer)
      Arg = argumentFor(Context->Call, Context->Callee, P);
    if (!Arg)
      return E;
    E = Arg;
  }
  return E;
}

std::optional<long long> evaluateInt(const Expr *E, ASTContext &Ctx, const CallContext *Context) {
  E = bindArguments(E, Context);
  Expr::EvalResult R;
  if (!E || E->isValueDependent() || !E->EvaluateAsInt(R, Ctx))
    return std::nullopt;
  return R.Val.getInt().getExtValue();
}

std::optional<std::string> evaluateNumber(const Expr *E, ASTContext &Ctx,
                                          const CallContext *Context) {
  E = bindArguments(E, Context);
  Expr::EvalResult R;
  if (!E || E->isValueDependent() || !E->EvaluateAsRValue(R, Ctx))
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
