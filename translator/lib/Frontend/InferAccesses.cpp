//===- InferAccesses.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/InferAccesses.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/ForceName.h"
#include "wash/translator/Frontend/GlobalWrites.h"
#include "wash/translator/Frontend/ParticleRoles.h"
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Frontend/TypeName.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/Attr.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/ExprCXX.h"

#include <map>
#include <set>
#include <tuple>

using namespace clang;

namespace wash::tr {
namespace {

/// One function body being analysed, with the roles of its variables.
struct Frame {
  llvm::DenseMap<const ValueDecl *, Roles> Vars;
  std::map<const CallExpr *, Roles> Calls;
  Roles Return = 0;
};

class KernelAnalyser {
public:
  KernelAnalyser(ProgramIndex &Index, Diagnoser &D, const Kernel &K, std::vector<Access> &Out,
                 SourceLocation KernelLoc, const std::vector<ParticleType> &Types)
      : Ctx(Index.context()), Index(Index), D(D), K(K), Out(Out), KernelLoc(KernelLoc),
        Types(Types), Walk(Index), Shared(Ctx, D, kernelKindName(K.Kind), K.Function) {}

  void run(const FunctionDecl *Def) {
    // The driver calls the kernel by its plain name, with no template arguments.
    if (Def->getPrimaryTemplate() || Def->getTemplateSpecializationKind() != TSK_Undeclared) {
      D.report(DiagId::KernelIsTemplate, KernelLoc, {K.Function});
      return;
    }
    std::vector<Roles> Params;
    if (K.Kind == KernelKind::Update || K.Kind == KernelKind::Force ||
        K.Kind == KernelKind::Reduction)
      Params.push_back(RoleOwn);
    if (K.Kind == KernelKind::Force)
      Params.push_back(RoleList);
    // Running for one type reads each particle's type, and keeping
    // neighbours of one type reads theirs (so halos carry it).
    if (!K.ParticleType.empty())
      add({TypeField, Target::Own, Mode::Read, std::nullopt, K.Pos});
    if (!K.NeighbourType.empty())
      add({TypeField, Target::Neighbour, Mode::Read, std::nullopt, K.Pos});
    AllowShared = allowsSharedState(Def);
    analyse(Def, Params, KernelLoc);
    reportEscapedLambdas();
  }

private:
  RoleEvaluator roles() {
    return RoleEvaluator([this](const ValueDecl *VD) { return varRoles(VD); },
                         [this](const CallExpr *CE) -> std::optional<Roles> {
                           auto It = Frames.back()->Calls.find(CE);
                           return It == Frames.back()->Calls.end() ? std::nullopt
                                                                   : std::optional(It->second);
                         });
  }
  Roles roleOf(const Expr *E) { return roles().of(E); }
  Roles varRoles(const ValueDecl *VD) const {
    // Innermost first: lambda bodies see their enclosing function's variables.
    for (auto It = Frames.rbegin(); It != Frames.rend(); ++It)
      if (auto F = (*It)->Vars.find(VD); F != (*It)->Vars.end())
        return F->second;
    return 0;
  }

  /// The roles FD returns, called at At with parameters of roles Params.
  Roles analyse(const FunctionDecl *FD, const std::vector<Roles> &Params, SourceLocation At) {
    auto Key = std::make_pair(FD->getCanonicalDecl(), Params);
    if (auto It = Memo.find(Key); It != Memo.end())
      return It->second;
    Roles Result = 0;
    switch (Walk.enter(FD, [&] { Result = analyseBody(FD, Params); })) {
    case CallWalk<>::Entry::Entered:
      break;
    case CallWalk<>::Entry::Recursive: {
      std::string Name = isLambda(FD) ? "lambda" : FD->getQualifiedNameAsString();
      D.report(DiagId::Recursion, At, {Name, K.Function});
      D.report(DiagId::NoteKernelRegisteredHere, KernelLoc, {K.Function});
      return 0;
    }
    case CallWalk<>::Entry::OverBudget:
      if (!std::exchange(BudgetReported, true))
        D.report(DiagId::AnalysisTooComplex, KernelLoc, {K.Function});
      return 0;
    }
    // Lambdas see their enclosing frame, so their results depend on more
    // than their parameters: only functions are memoised.
    if (!isLambda(FD))
      Memo[Key] = Result;
    return Result;
  }

  Roles analyseBody(const FunctionDecl *FD, const std::vector<Roles> &Params) {
    if (isLambda(FD))
      AnalysedLambdas.insert(cast<CXXMethodDecl>(FD)->getParent());
    Frame F;
    for (unsigned I = 0; I < FD->getNumParams() && I < Params.size(); ++I)
      F.Vars[FD->getParamDecl(I)] = Params[I];
    Frames.push_back(&F);
    // Flow-insensitive: first let variable roles reach a fixed point, so a
    // variable assigned a neighbour late counts as a neighbour everywhere.
    for (unsigned Round = 0; Round < 8 && bind(FD->getBody()); ++Round)
      ;
    record(FD->getBody());
    Frames.pop_back();
    return F.Return;
  }

  static bool isLambda(const FunctionDecl *FD) {
    const auto *MD = dyn_cast<CXXMethodDecl>(FD);
    return MD && MD->getParent()->isLambda();
  }

  /// Adds Roles to variable VD; true if that changed anything.
  bool join(const ValueDecl *VD, Roles R) {
    Roles &Slot = Frames.back()->Vars[VD];
    Roles Old = Slot;
    Slot |= R;
    return Slot != Old;
  }

  /// The variable an assignment or initialisation stores into, if any.
  static const ValueDecl *assignedVar(const Expr *LHS) {
    const auto *DRE = dyn_cast<DeclRefExpr>(LHS->IgnoreParenImpCasts());
    return DRE ? DRE->getDecl() : nullptr;
  }

  bool bind(const Stmt *S) {
    if (!S)
      return false;
    bool Changed = false;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      for (const Expr *Init : L->capture_inits())
        Changed |= bind(Init);
      return Changed;
    }
    for (const Stmt *Child : S->children())
      Changed |= bind(Child);
    if (const auto *DS = dyn_cast<DeclStmt>(S))
      for (const Decl *Dcl : DS->decls())
        if (const auto *VD = dyn_cast<VarDecl>(Dcl); VD && VD->getInit())
          Changed |= join(VD, roleOf(VD->getInit()));
    if (auto [Var, Value] = assignment(S); Var)
      Changed |= join(Var, roleOf(Value));
    return Changed;
  }

  /// `v = e` with v a variable, built-in or overloaded.
  static std::pair<const ValueDecl *, const Expr *> assignment(const Stmt *S) {
    if (const auto *B = dyn_cast<BinaryOperator>(S); B && B->getOpcode() == BO_Assign)
      return {assignedVar(B->getLHS()), B->getRHS()};
    if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(S);
        OC && OC->getOperator() == OO_Equal && OC->getNumArgs() == 2)
      return {assignedVar(OC->getArg(0)), OC->getArg(1)};
    return {nullptr, nullptr};
  }

  /// Children first, so that calls nested in an expression are analysed
  /// (and their result roles known) before the expression that uses them.
  void record(const Stmt *S) {
    if (!S)
      return;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      for (const Expr *Init : L->capture_inits())
        record(Init); // The body is analysed where the lambda is called.
      if (usesParticle(L))
        ParticleLambdas.push_back(L);
      return;
    }
    if (const auto *CE = dyn_cast<CallExpr>(S))
      DirectCallees.insert(CE->getCallee()->IgnoreParenImpCasts());
    if (const auto *DRE = dyn_cast<DeclRefExpr>(S))
      functionReference(DRE);
    for (const Stmt *Child : S->children())
      record(Child);
    if (const auto *DS = dyn_cast<DeclStmt>(S))
      for (const Decl *Dcl : DS->decls())
        if (const auto *VD = dyn_cast<VarDecl>(Dcl); VD && VD->getInit())
          join(VD, roleOf(VD->getInit()));
    if (auto [Var, Value] = assignment(S); Var)
      join(Var, roleOf(Value));
    if (const auto *RS = dyn_cast<ReturnStmt>(S); RS && RS->getRetValue())
      Frames.back()->Return |= roleOf(RS->getRetValue());
    if (const auto *CE = dyn_cast<CallExpr>(S))
      call(CE);
    globalWrite(S);
  }

  void call(const CallExpr *CE);
  bool usesParticle(const LambdaExpr *L);
  void functionReference(const DeclRefExpr *DRE);
  bool opaqueCallable(const CallExpr *CE);
  bool particleThroughTemplate(const FunctionDecl *FD, const std::vector<Roles> &Params,
                               SourceLocation Loc);
  void reportEscapedLambdas();
  void globalWrite(const Stmt *S);
  void particleMethod(const CallExpr *CE, const FunctionDecl *FD);
  bool particleType(const CallExpr *CE, const clang::Expr *NameArg, const ParticleAccessor &P,
                    Roles R);
  void libraryCall(const CallExpr *CE);
  bool libraryHelperCall(const CallExpr *CE, const FunctionDecl *FD);
  void userCall(const CallExpr *CE, const FunctionDecl *FD);
  void add(Access A) {
    if (Recorded.insert(std::make_tuple(A.Field, A.On, A.How, A.Pos.Line, A.Pos.Col)).second)
      Out.push_back(std::move(A));
  }
  bool anyParticleArg(const CallExpr *CE) {
    for (const Expr *A : CE->arguments())
      if (roleOf(A) || involvesParticle(A->getType()))
        return true;
    return false;
  }

  ASTContext &Ctx;
  ProgramIndex &Index;
  Diagnoser &D;
  const Kernel &K;
  std::vector<Access> &Out; ///< The kernel's Kernel::Accesses.
  SourceLocation KernelLoc;
  const std::vector<ParticleType> &Types;
  std::vector<Frame *> Frames;
  CallWalk<> Walk;
  bool BudgetReported = false;
  std::map<std::pair<const FunctionDecl *, std::vector<Roles>>, Roles> Memo;
  std::set<std::tuple<std::string, Target, Mode, unsigned, unsigned>> Recorded;
  // Escapes: particles reaching code the analysis does not follow.
  std::set<const Expr *> DirectCallees;
  std::vector<const LambdaExpr *> ParticleLambdas;
  std::set<const CXXRecordDecl *> AnalysedLambdas;
  SharedStateFinder Shared;
  bool AllowShared = false; ///< The kernel calls wash::allow_shared_state().
};

void KernelAnalyser::call(const CallExpr *CE) {
  const FunctionDecl *FD = CE->getDirectCallee();
  if (!FD) {
    if (anyParticleArg(CE))
      D.report(DiagId::IndirectCall, CE->getBeginLoc(), {K.Function});
    return;
  }
  if (isParticleMethod(FD))
    return particleMethod(CE, FD);
  if (isWashCall(FD, ApiCall::create_particle)) {
    if (K.Kind != KernelKind::Init) {
      D.report(DiagId::CreateOutsideInit, CE->getBeginLoc(), {kernelKindName(K.Kind), K.Function});
      return;
    }
    for (const BuiltinField &F : builtinFields())
      if (F.Created)
        add({F.Name, Target::Own, Mode::Write, std::nullopt, D.toPos(CE->getBeginLoc())});
    return;
  }
  if (isWashCall(FD, ApiCall::stop) && K.Kind != KernelKind::Void) {
    D.report(DiagId::StopOutsideVoidKernel, CE->getBeginLoc(),
             {kernelKindName(K.Kind), K.Function});
    return;
  }
  if (isWashCall(FD, ApiCall::set_variable) &&
      (K.Kind == KernelKind::Update || K.Kind == KernelKind::Force ||
       K.Kind == KernelKind::Reduction)) {
    D.report(DiagId::VariableWriteInParticleKernel, CE->getBeginLoc(),
             {kernelKindName(K.Kind), K.Function});
    return;
  }
  if (isWashCall(FD, ApiCall::set_time_step) &&
      (K.Kind == KernelKind::Update || K.Kind == KernelKind::Force ||
       K.Kind == KernelKind::Reduction)) {
    D.report(DiagId::TimeStepWriteInParticleKernel, CE->getBeginLoc(),
             {kernelKindName(K.Kind), K.Function});
    return;
  }
  if (isWashFunction(FD)) {
    // User code in namespace wash is not the API, but is not followed either.
    if (!washCall(FD) && Index.isUserFunction(FD) && anyParticleArg(CE))
      D.report(DiagId::HelperInWashNamespace, CE->getBeginLoc(), {FD->getQualifiedNameAsString()});
    return;
  }
  const auto *MD = dyn_cast<CXXMethodDecl>(FD);
  if (MD && MD->isVirtual() && !MD->hasAttr<FinalAttr>() &&
      !MD->getParent()->hasAttr<FinalAttr>() && anyParticleArg(CE)) {
    D.report(DiagId::IndirectCall, CE->getBeginLoc(), {K.Function});
    return;
  }
  if (Index.isUserFunction(FD))
    return userCall(CE, FD);
  if (libraryHelperCall(CE, FD))
    return;
  libraryCall(CE);
}

/// A function of a system or library header declared to take a particle
/// (`double mass(const wash::Particle &)`), given one: wash rewrites only the
/// user's files, so the generated code would hand it a column handle it
/// cannot take. Reported at the call. Templates (the standard library's
/// among them) are left alone: they may well take what the generated code
/// passes.
bool KernelAnalyser::libraryHelperCall(const CallExpr *CE, const FunctionDecl *FD) {
  if (FD->isTemplateInstantiation() || FD->getDescribedFunctionTemplate())
    return false;
  if (const auto *MD = dyn_cast<CXXMethodDecl>(FD);
      MD && MD->getParent()->getTemplateInstantiationPattern())
    return false;
  bool Takes = false;
  for (const ParmVarDecl *P : FD->parameters())
    Takes |= involvesParticle(P->getType());
  bool Given = false;
  for (const Expr *A : CE->arguments())
    Given |= (roleOf(A) & (RoleOwn | RoleNeighbour | RoleList)) != 0;
  if (!Takes || !Given)
    return false;
  const SourceManager &SM = Ctx.getSourceManager();
  const FunctionDecl *Where = FD->getDefinition() ? FD->getDefinition() : FD;
  PresumedLoc P = SM.getPresumedLoc(SM.getExpansionLoc(Where->getLocation()));
  D.report(DiagId::HelperInLibraryHeader, CE->getBeginLoc(),
           {FD->getQualifiedNameAsString(), P.isValid() ? P.getFilename() : "?"});
  D.report(DiagId::NoteDeclaredHere, Where->getLocation(), {FD->getQualifiedNameAsString()});
  return true;
}

void KernelAnalyser::particleMethod(const CallExpr *CE, const FunctionDecl *FD) {
  const Expr *Object = nullptr;
  unsigned FirstArg = 0;
  if (const auto *MC = dyn_cast<CXXMemberCallExpr>(CE)) {
    Object = MC->getImplicitObjectArgument();
  } else if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(CE); OC && OC->getNumArgs() > 0) {
    Object = OC->getArg(0);
    FirstArg = 1;
  }
  if (!Object)
    return;
  Roles R = roleOf(Object);
  std::string Method = FD->getNameAsString();
  if (FD->getOverloadedOperator() == OO_Equal) {
    // Assigning a handle rebinds a variable (handled by bind/record) unless
    // it overwrites a neighbour's handle in place.
    if (R & RoleNeighbour && !assignedVar(Object))
      D.report(DiagId::NeighbourWrite, CE->getExprLoc(), {"operator="});
    return;
  }
  auto P = particleAccessor(FD);
  if (!P)
    return;
  std::string Field;
  std::optional<ForceKind> Kind; // Set for forces only: which accessor was used.
  if (P->IsType) {
    if (CE->getNumArgs() <= FirstArg || !particleType(CE, CE->getArg(FirstArg), *P, R))
      return;
    Field = TypeField;
  } else if (P->isForce()) {
    if (CE->getNumArgs() <= FirstArg)
      return;
    const Expr *NameArg = CE->getArg(FirstArg);
    auto Name = forceName(NameArg, Ctx, D);
    if (!Name)
      return;
    Field = *Name;
    Kind = P->Kind;
  } else {
    Field = P->Field->Name;
  }
  SourceLocation Loc = CE->getExprLoc();
  if (!(R & (RoleOwn | RoleNeighbour))) {
    D.report(DiagId::UnknownParticle, Loc, {Method});
    return;
  }
  if (R & RoleOwn)
    add({Field, Target::Own, P->How, Kind, D.toPos(Loc)});
  if (R & RoleNeighbour) {
    if (P->How == Mode::Write)
      D.report(DiagId::NeighbourWrite, Loc, {Method});
    else
      add({Field, Target::Neighbour, P->How, Kind, D.toPos(Loc)});
  }
}

/// is_type and set_type: a known type; set_type only by init and update
/// kernels, on their own particle.
bool KernelAnalyser::particleType(const CallExpr *CE, const Expr *NameArg,
                                  const ParticleAccessor &P, Roles R) {
  if (!knownParticleType(NameArg, Ctx, D, Types))
    return false;
  if (P.How != Mode::Write)
    return true;
  if (R & RoleNeighbour) {
    D.report(DiagId::SetTypeOnNeighbour, CE->getExprLoc());
    return false;
  }
  if (K.Kind != KernelKind::Init && K.Kind != KernelKind::Update) {
    D.report(DiagId::SetTypeOutsideKernel, CE->getExprLoc(), {kernelKindName(K.Kind), K.Function});
    return false;
  }
  return true;
}

/// The lambda an argument evaluates to, looking through copies and variables.
static const LambdaExpr *lambdaOf(const Expr *E) {
  PeelOptions Through;
  Through.VariableInitialisers = true;
  Through.IsCopy = constructsFromOneArgument;
  return dyn_cast_or_null<LambdaExpr>(peel(E, Through));
}

/// Standard library calls are not followed, except into lambdas they are
/// given: std::for_each(ns.begin(), ns.end(), [&](const Particle &n) {...})
/// calls the lambda with what the other arguments hold.
void KernelAnalyser::libraryCall(const CallExpr *CE) {
  if (opaqueCallable(CE))
    return;
  Roles Given = 0;
  for (const Expr *A : CE->arguments())
    Given |= derefRoles(roleOf(A)) | (roleOf(A) & (RoleOwn | RoleNeighbour));
  for (const Expr *A : CE->arguments()) {
    const LambdaExpr *L = lambdaOf(A);
    if (!L)
      continue;
    std::vector<const FunctionDecl *> Operators;
    if (const FunctionTemplateDecl *T = L->getDependentCallOperator())
      for (const FunctionDecl *Spec : T->specializations())
        Operators.push_back(Spec);
    else
      Operators.push_back(L->getCallOperator());
    for (const FunctionDecl *Op : Operators) {
      if (!Op->hasBody())
        continue;
      std::vector<Roles> Params;
      for (const ParmVarDecl *P : Op->parameters())
        Params.push_back(involvesParticle(P->getType()) ? Given : 0);
      if (!particleThroughTemplate(Op, Params, CE->getBeginLoc()))
        analyse(Op, Params, CE->getBeginLoc());
    }
  }
}

/// Per-particle kernels changing global, static or library state: the
/// result depends on the order particles are visited in, which backends and
/// ranks do not share. Reading globals (set in main) is fine.
void KernelAnalyser::globalWrite(const Stmt *S) {
  if ((K.Kind == KernelKind::Update || K.Kind == KernelKind::Force ||
       K.Kind == KernelKind::Reduction) &&
      !AllowShared)
    Shared.visit(S);
}

/// A particle bound to a parameter whose type is a template parameter
/// (`auto &q`, `P &p`): the source is rewritten once, from the template, and
/// only accesses written against wash::Particle can be rewritten.
bool KernelAnalyser::particleThroughTemplate(const FunctionDecl *FD,
                                             const std::vector<Roles> &Params, SourceLocation Loc) {
  const FunctionDecl *Pattern = FD->getTemplateInstantiationPattern();
  if (!Pattern)
    return false;
  for (unsigned I = 0; I < Params.size() && I < Pattern->getNumParams(); ++I) {
    const ParmVarDecl *P = Pattern->getParamDecl(I);
    if ((Params[I] || involvesParticle(FD->getParamDecl(I)->getType())) &&
        P->getType()->isDependentType()) {
      std::string Name = isLambda(FD) ? "lambda" : "'" + FD->getQualifiedNameAsString() + "'";
      D.report(DiagId::ParticleThroughTemplate, Loc, {Name});
      D.report(DiagId::NoteDeclaredHere, P->getLocation(), {P->getNameAsString()});
      if (isLambda(FD)) // Reported here rather than as an escape.
        AnalysedLambdas.insert(cast<CXXMethodDecl>(FD)->getParent());
      return true;
    }
  }
  return false;
}

/// A lambda capturing a particle variable or taking particle parameters.
bool KernelAnalyser::usesParticle(const LambdaExpr *L) {
  for (const LambdaCapture &C : L->captures())
    if (C.capturesVariable())
      if (const ValueDecl *VD = C.getCapturedVar();
          VD && (involvesParticle(VD->getType()) || varRoles(VD)))
        return true;
  std::vector<const FunctionDecl *> Operators{L->getCallOperator()};
  if (const FunctionTemplateDecl *T = L->getDependentCallOperator())
    for (const FunctionDecl *Spec : T->specializations())
      Operators.push_back(Spec);
  for (const FunctionDecl *Op : Operators)
    for (const ParmVarDecl *P : Op->parameters())
      if (involvesParticle(P->getType()))
        return true;
  return false;
}

/// A function taking a particle, named other than as a call's callee: the
/// calls made through the pointer or std::function are not followed.
void KernelAnalyser::functionReference(const DeclRefExpr *DRE) {
  const auto *FD = dyn_cast<FunctionDecl>(DRE->getDecl());
  if (!FD || DirectCallees.count(DRE) || isWashFunction(FD) || !Index.isUserFunction(FD))
    return;
  for (const ParmVarDecl *P : FD->parameters())
    if (involvesParticle(P->getType())) {
      D.report(DiagId::FunctionEscapes, DRE->getLocation(), {FD->getQualifiedNameAsString()});
      return;
    }
}

/// A particle handed to a callable the analysis cannot see into: a
/// std::function's operator(), std::invoke(f, p)...; lambdas are followed.
bool KernelAnalyser::opaqueCallable(const CallExpr *CE) {
  bool GivesParticle = false;
  unsigned First = 0;
  const auto *OC = dyn_cast<CXXOperatorCallExpr>(CE);
  bool CallsObject = OC && OC->getOperator() == OO_Call && OC->getNumArgs() > 0;
  if (CallsObject && !lambdaOf(OC->getArg(0)))
    First = 1;
  else
    CallsObject = false;
  for (unsigned I = First; I < CE->getNumArgs(); ++I) {
    const Expr *A = CE->getArg(I);
    if (roleOf(A) & (RoleOwn | RoleNeighbour) || involvesParticle(A->getType()))
      GivesParticle = true;
  }
  if (!GivesParticle)
    return false;
  bool Opaque = CallsObject;
  for (unsigned I = First; I < CE->getNumArgs() && !Opaque; ++I) {
    const Expr *A = CE->getArg(I);
    QualType T = A->getType().getNonReferenceType();
    if (lambdaOf(A))
      continue;
    if (T->isFunctionPointerType() || T->isFunctionType() || T->isMemberFunctionPointerType())
      Opaque = true;
    else if (const CXXRecordDecl *RD = T->getAsCXXRecordDecl();
             RD && RD->hasDefinition() && !RD->isLambda())
      for (const CXXMethodDecl *M : RD->methods())
        if (M->getOverloadedOperator() == OO_Call)
          Opaque = true;
  }
  if (!Opaque)
    return false;
  const FunctionDecl *FD = CE->getDirectCallee();
  PrintingPolicy PP = Ctx.getPrintingPolicy();
  std::string Name =
      CallsObject
          ? OC->getArg(0)->getType().getNonReferenceType().getUnqualifiedType().getAsString(PP)
          : FD->getQualifiedNameAsString();
  D.report(DiagId::CallableEscapes, CE->getBeginLoc(), {Name});
  return true;
}

/// Lambdas using a particle that no call the analysis followed ran: stored
/// in a std::thread, a std::function called elsewhere...
void KernelAnalyser::reportEscapedLambdas() {
  for (const LambdaExpr *L : ParticleLambdas)
    if (!AnalysedLambdas.count(L->getLambdaClass()))
      D.report(DiagId::LambdaEscapes, L->getBeginLoc());
}

void KernelAnalyser::userCall(const CallExpr *CE, const FunctionDecl *FD) {
  const FunctionDecl *Def = FD->getDefinition();
  if (!Def || !Def->hasBody()) {
    if (anyParticleArg(CE)) {
      D.report(DiagId::HelperNotDefined, CE->getBeginLoc(), {FD->getQualifiedNameAsString()});
      D.report(DiagId::NoteDeclaredHere, FD->getLocation(), {FD->getQualifiedNameAsString()});
    }
    return;
  }
  // A member operator call (a lambda's operator()) passes the object first.
  unsigned Skip = isa<CXXOperatorCallExpr>(CE) && isa<CXXMethodDecl>(FD) ? 1 : 0;
  std::vector<Roles> Params;
  for (unsigned I = Skip; I < CE->getNumArgs(); ++I)
    Params.push_back(roleOf(CE->getArg(I)));
  if (particleThroughTemplate(Def, Params, CE->getBeginLoc()))
    return;
  Frames.back()->Calls[CE] = analyse(Def, Params, CE->getBeginLoc());
}

} // namespace

std::optional<std::vector<std::vector<Access>>>
inferAccesses(ProgramIndex &Index, Diagnoser &D, const AstRefs &Refs,
              const std::vector<Kernel> &Kernels, const std::vector<ParticleType> &Types) {
  std::vector<std::vector<Access>> Accesses(Kernels.size());
  for (unsigned I = 0; I < Kernels.size(); ++I) {
    KernelAnalyser A(Index, D, Kernels[I], Accesses[I], D.fromPos(Kernels[I].Pos), Types);
    A.run(Refs.Kernels[I]);
  }
  if (D.hasErrors())
    return std::nullopt;
  return Accesses;
}

} // namespace wash::tr
