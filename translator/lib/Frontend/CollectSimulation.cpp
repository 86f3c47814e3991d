//===- CollectSimulation.cpp ----------------------------------------------===//
#include "wash/translator/Frontend/CollectSimulation.h"
#include "wash/translator/Frontend/CheckRegistrationFlow.h"
#include "wash/translator/Frontend/ForceName.h"
#include "wash/translator/Frontend/ParameterBindings.h"
#include "wash/translator/Frontend/ResolveKernel.h"
#include "wash/translator/Frontend/TypeName.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ExprCXX.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/AST/StmtCXX.h"

#include <algorithm>
#include <set>

using namespace clang;

namespace wash::tr {
namespace {

class Collector {
public:
  Collector(ProgramIndex &Index, Diagnoser &D, Registrations &M, AstRefs &Refs)
      : Ctx(Index.context()), Index(Index), D(D), M(M), Refs(Refs), Walk(Index) {}

  /// Each call is walked where it happens, as if inlined: a helper called
  /// twice registers twice at run time too. Recursion and a budget against
  /// hostile call trees bound the walk (the program index's).
  void walkFunction(const FunctionDecl *FD, bool InLoop, SourceLocation At) {
    if (FD->hasBody() &&
        Walk.enter(FD, [&] { walk(FD->getBody(), InLoop); }) == CallWalk<>::Entry::OverBudget)
      reportBudget(At);
  }

  void reportBudget(SourceLocation At) {
    if (Index.firstOverrun())
      D.report(DiagId::ProgramTooComplex, At, {std::to_string(Index.budget())});
  }

  /// Source locations of the registration calls the walk reached: compared by
  /// location because templates have one call node per instantiation.
  std::set<unsigned> Reached;

private:
  void walk(const Stmt *S, bool InLoop) {
    if (!S)
      return;
    if (isa<ForStmt, WhileStmt, DoStmt, CXXForRangeStmt>(S))
      InLoop = true;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      // The body runs when the lambda is called, and is walked then.
      for (const Expr *Init : L->capture_inits())
        walk(Init, InLoop);
      return;
    }
    if (const auto *DS = dyn_cast<DeclStmt>(S))
      return declarations(DS, InLoop);
    // Operands and arguments first: C++ evaluates them before the call.
    unsigned Registering = 0;
    for (const Stmt *Child : S->children()) {
      unsigned Before = RegistrationCount;
      walk(Child, InLoop);
      Registering += RegistrationCount > Before;
    }
    if (Registering > 1 && !sequencedLeftToRight(S))
      D.report(DiagId::RegistrationUnsequenced, S->getBeginLoc());
    if (const auto *CE = dyn_cast<CallExpr>(S))
      call(CE, InLoop);
  }

  /// A static local's initialiser runs the first time only: what it
  /// registers depends on how often its function is called.
  void declarations(const DeclStmt *DS, bool InLoop) {
    for (const Decl *Dcl : DS->decls()) {
      unsigned Before = RegistrationCount;
      const auto *VD = dyn_cast<VarDecl>(Dcl);
      if (!VD)
        continue;
      if (const Expr *Init = VD->getInit())
        walk(Init, InLoop);
      if (VD->isStaticLocal() && RegistrationCount > Before)
        D.report(DiagId::RegistrationInStaticInit, VD->getLocation(), {VD->getName().str()});
    }
  }

  /// Whether C++ evaluates S's operands in the order the walk visits them
  /// (C++17): a comma, && and ||, << and >>, a subscript, ?: (its condition
  /// first), and braced lists. Function arguments, the other operators and
  /// assignment (right before left) are not.
  static bool sequencedLeftToRight(const Stmt *S) {
    if (const auto *B = dyn_cast<BinaryOperator>(S))
      return B->getOpcode() == BO_Comma || B->isLogicalOp() || B->isShiftOp();
    if (const auto *Op = dyn_cast<CXXOperatorCallExpr>(S)) {
      switch (Op->getOperator()) {
      case OO_Comma:
      case OO_AmpAmp:
      case OO_PipePipe:
      case OO_LessLess:
      case OO_GreaterGreater:
      case OO_Subscript:
        return true;
      default:
        return false;
      }
    }
    if (const auto *C = dyn_cast<CXXConstructExpr>(S))
      return C->isListInitialization();
    if (isa<CallExpr, CXXNewExpr>(S))
      return false;
    // Statements run in order; other expressions have one operand that can
    // register, or sequence theirs (?:, InitListExpr).
    return true;
  }

  void call(const CallExpr *CE, bool InLoop) {
    const FunctionDecl *FD = CE->getDirectCallee();
    if (!FD)
      return;
    if (isNonLocalJump(FD))
      D.report(DiagId::RegistrationWithLongJump, CE->getBeginLoc(), {FD->getName().str()});
    if (const ApiCallInfo *Call = washCall(FD); Call && Call->readFromMain()) {
      ++RegistrationCount;
      Reached.insert(CE->getBeginLoc().getRawEncoding());
      registration(CE, *Call, InLoop);
      return;
    }
    const FunctionDecl *Def = FD->getDefinition();
    if (!Def || !Index.isUserFunction(Def))
      return;
    // The callee's parameters are bound to this call's arguments.
    CallContext Inner{CE, Def, Current};
    Current = &Inner;
    walkFunction(Def, InLoop, CE->getBeginLoc());
    Current = Inner.Outer;
  }

  /// setjmp and longjmp: a jump back re-runs registrations the walk reads
  /// once, or a jump out skips them.
  static bool isNonLocalJump(const FunctionDecl *FD) {
    static const std::set<std::string> Names = {"setjmp",     "_setjmp",      "__sigsetjmp",
                                                "sigsetjmp",  "longjmp",      "_longjmp",
                                                "siglongjmp", "__longjmp_chk"};
    return FD->getIdentifier() && FD->getDeclContext()->getRedeclContext()->isTranslationUnit() &&
           Names.count(FD->getName().str());
  }

  SettingValue value(const Expr *E, std::optional<std::string> Constant) {
    SettingValue V;
    V.Constant = Constant.has_value();
    V.Text = Constant ? *Constant : sourceText(E, Ctx);
    V.Pos = D.toPos(E->getBeginLoc());
    return V;
  }

  static std::optional<std::string> quoted(std::optional<std::string> S) {
    if (!S)
      return std::nullopt;
    return "\"" + *S + "\"";
  }

  /// set_smoothing_length_support's rule: the generated search depends on
  /// it, so it must be a constant (wash::Support::Gather when left out).
  void supportRule(const CallExpr *CE) {
    if (CE->getNumArgs() < 2 || isa<CXXDefaultArgExpr>(CE->getArg(1)->IgnoreImplicit()))
      return;
    const Expr *Rule = CE->getArg(1);
    auto V = evaluateInt(Rule, Ctx, Current);
    if (!V || (*V != 0 && *V != 1)) {
      D.report(DiagId::SupportRuleNotConstant, Rule->getExprLoc());
      return;
    }
    M.Sim.SymmetricSupport = *V == 1; // wash::Support::Symmetric
  }

  void registration(const CallExpr *CE, const ApiCallInfo &Call, bool InLoop) {
    if (Call.Use == CallUse::MainOnce && InLoop) {
      D.report(DiagId::RegistrationInLoop, CE->getBeginLoc(), {Call.Name});
      return;
    }
    if (Call.Kernel)
      return kernel(CE, *Call.Kernel);
    const Expr *Arg = CE->getNumArgs() ? CE->getArg(0) : nullptr;
    // Every call is listed, so that -Wswitch points here for a new one.
    switch (Call.Id) {
    case ApiCall::start:
      M.Sim.CallsStart = true;
      break;
    case ApiCall::set_precision:
      if (auto S = evaluateString(Arg, Ctx, Current); S && (*S == "double" || *S == "float"))
        M.Sim.Precision = *S;
      else
        D.report(DiagId::PrecisionInvalid, Arg->getExprLoc());
      break;
    case ApiCall::set_influence_radius:
      M.Sim.InfluenceRadius = value(Arg, evaluateNumber(Arg, Ctx, Current));
      break;
    case ApiCall::set_smoothing_length_support:
      M.Sim.SmoothingLengthSupport = value(Arg, evaluateNumber(Arg, Ctx, Current));
      supportRule(CE);
      break;
    case ApiCall::set_max_iterations: {
      auto N = evaluateInt(Arg, Ctx, Current);
      M.Sim.MaxIterations = value(Arg, N ? std::optional(std::to_string(*N)) : std::nullopt);
      break;
    }
    case ApiCall::set_simulation_name:
      M.Sim.SimulationNames.push_back(value(Arg, quoted(evaluateString(Arg, Ctx, Current))));
      break;
    case ApiCall::set_output_file_name:
      M.Sim.OutputFileNames.push_back(value(Arg, quoted(evaluateString(Arg, Ctx, Current))));
      break;
    case ApiCall::add_force:
      addForce(CE);
      break;
    case ApiCall::add_particle_type:
      addParticleType(CE);
      break;
    case ApiCall::set_bounding_box:
    case ApiCall::add_variable:
    case ApiCall::set_end_time:
      break; // Run-time settings: the generated program makes the same call.
    case ApiCall::add_init_kernel:
    case ApiCall::add_update_kernel:
    case ApiCall::add_force_kernel:
    case ApiCall::add_void_kernel:
    case ApiCall::add_reduction_kernel:
    case ApiCall::get_variable:
    case ApiCall::set_variable:
    case ApiCall::get_time:
    case ApiCall::get_time_step:
    case ApiCall::set_time_step:
    case ApiCall::get_end_time:
    case ApiCall::create_particle:
    case ApiCall::stop:
      break; // Kernels are registered above; the rest is not read from main.
    }
  }

  void kernel(const CallExpr *CE, KernelKind Kind) {
    const FunctionDecl *Def = resolveKernel(CE, Kind, Ctx, D);
    if (!Def)
      return;
    Kernel K;
    K.Kind = Kind;
    if (Kind == KernelKind::Reduction && !reduction(CE, K))
      return;
    if (!kernelTypes(CE, K))
      return;
    K.Function = Def->getQualifiedNameAsString();
    K.Pos = D.toPos(CE->getBeginLoc());
    M.Kernels.push_back(K);
    Refs.Kernels.push_back(Def);
  }

  /// The operation and variable of `add_reduction_kernel(&f, op, "variable")`.
  bool reduction(const CallExpr *CE, Kernel &K) {
    auto Op = evaluateInt(CE->getArg(1), Ctx, Current);
    auto Var = evaluateString(CE->getArg(2), Ctx, Current);
    if (!Op || *Op < 0 || *Op > 2) {
      D.report(DiagId::ReductionNotConstant, CE->getArg(1)->getExprLoc(), {"operation"});
      return false;
    }
    if (!Var) {
      D.report(DiagId::ReductionNotConstant, CE->getArg(2)->getExprLoc(), {"variable"});
      return false;
    }
    static const char *Ops[] = {"sum", "min", "max"};
    K.ReduceOp = Ops[*Op];
    K.Variable = *Var;
    return true;
  }

  /// The optional particle and neighbour types of a kernel registration:
  /// add_update_kernel(&f, "fluid"), add_force_kernel(&f, "wall", "fluid"),
  /// add_reduction_kernel(&f, op, "var", "fluid"). A default argument is "".
  bool kernelTypes(const CallExpr *CE, Kernel &K) {
    unsigned First = K.Kind == KernelKind::Reduction ? 3 : 1;
    unsigned Count = K.Kind == KernelKind::Force                                       ? 2
                     : K.Kind == KernelKind::Update || K.Kind == KernelKind::Reduction ? 1
                                                                                       : 0;
    std::string *Into[] = {&K.ParticleType, &K.NeighbourType};
    for (unsigned I = 0; I < Count; ++I) {
      if (First + I >= CE->getNumArgs())
        break;
      const Expr *Arg = CE->getArg(First + I);
      if (isa<CXXDefaultArgExpr>(Arg))
        continue;
      // "" is every type, as the default argument says.
      if (auto S = evaluateString(Arg, Ctx, Current); S && S->empty())
        continue;
      auto Name = knownParticleType(Arg, Ctx, D, M.Types, Current);
      if (!Name)
        return false;
      *Into[I] = *Name;
    }
    return true;
  }

  void addParticleType(const CallExpr *CE) {
    const Expr *NameArg = CE->getArg(0);
    auto Name = particleTypeName(NameArg, Ctx, D, Current);
    if (!Name)
      return;
    for (const ParticleType &T : M.Types)
      if (T.Name == *Name) {
        D.report(DiagId::ParticleTypeAddedTwice, NameArg->getExprLoc(), {*Name});
        D.report(DiagId::NoteRegisteredHere, D.fromPos(T.Pos), {*Name});
        return;
      }
    M.Types.push_back({*Name, D.toPos(NameArg->getExprLoc())});
  }

  void addForce(const CallExpr *CE) {
    const Expr *NameArg = CE->getArg(0), *DimArg = CE->getArg(1);
    auto Name = forceName(NameArg, Ctx, D, Current);
    if (!Name)
      return;
    unsigned SimDim = M.Sim.Dimension;
    auto Dim = evaluateInt(DimArg, Ctx, Current);
    if (!Dim) {
      D.report(DiagId::ForceDimNotConstant, DimArg->getExprLoc(), {*Name});
      return;
    }
    if (*Dim != 1 && *Dim != SimDim) {
      D.report(DiagId::ForceDimInvalid, DimArg->getExprLoc(),
               {*Name, std::to_string(*Dim), std::to_string(SimDim)});
      return;
    }
    for (const ForceRegistration &R : M.Forces)
      if (R.Name == *Name) {
        D.report(DiagId::ForceRegisteredTwice, NameArg->getExprLoc(), {*Name});
        D.report(DiagId::NoteRegisteredHere, D.fromPos(R.Pos), {*Name});
        return;
      }
    M.Forces.push_back(
        {*Name, *Dim == 1 ? ForceKind::Scalar : ForceKind::Vector, D.toPos(NameArg->getExprLoc())});
  }

  ASTContext &Ctx;
  ProgramIndex &Index;
  Diagnoser &D;
  Registrations &M;
  AstRefs &Refs;
  CallWalk<> Walk;
  /// Registration calls reached so far.
  unsigned RegistrationCount = 0;
  /// The calls the walk followed to where it is: what binds the parameters.
  const CallContext *Current = nullptr;
};

/// Registration calls and references in user code that the walk from main
/// did not account for.
class Stragglers : public RecursiveASTVisitor<Stragglers> {
public:
  Stragglers(const SourceManager &SM, Diagnoser &D, const std::set<unsigned> &Reached)
      : SM(SM), D(D), Reached(Reached) {}

  bool TraverseDecl(Decl *Dcl) {
    // The API's own headers declare these functions; only user code matters.
    if (Dcl && !isa<TranslationUnitDecl>(Dcl) && !isUserCode(SM, Dcl))
      return true;
    return RecursiveASTVisitor::TraverseDecl(Dcl);
  }

  bool VisitCallExpr(CallExpr *CE) {
    const FunctionDecl *FD = CE->getDirectCallee();
    if (!isRegistrationFunction(FD))
      return true;
    Callees.insert(CE->getCallee()->IgnoreParenImpCasts());
    if (!Reached.count(CE->getBeginLoc().getRawEncoding()))
      D.report(DiagId::RegistrationUnreachable, CE->getBeginLoc(), {FD->getName().str()});
    return true;
  }

  bool VisitDeclRefExpr(DeclRefExpr *DRE) {
    const auto *FD = dyn_cast<FunctionDecl>(DRE->getDecl());
    if (isRegistrationFunction(FD) && !Callees.count(DRE))
      D.report(DiagId::RegistrationIndirect, DRE->getLocation(), {FD->getName().str()});
    return true;
  }

private:
  const SourceManager &SM;
  Diagnoser &D;
  const std::set<unsigned> &Reached;
  std::set<const Expr *> Callees;
};

} // namespace

std::optional<Registrations> collectSimulation(ProgramIndex &Index, Diagnoser &D,
                                               unsigned Dimension, AstRefs &Refs) {
  ASTContext &Ctx = Index.context();
  Refs.Main = Index.main();
  if (!Refs.Main) {
    SourceManager &SM = Ctx.getSourceManager();
    D.report(DiagId::NoMain, SM.getLocForStartOfFile(SM.getMainFileID()));
    return std::nullopt;
  }
  Registrations M;
  M.Sim.Dimension = Dimension;
  Collector C(Index, D, M, Refs);
  C.walkFunction(Refs.Main, /*InLoop=*/false, Refs.Main->getLocation());
  if (Index.overran())
    return std::nullopt; // Reported: what the walk did not reach is unknown.
  Stragglers S(Ctx.getSourceManager(), D, C.Reached);
  S.TraverseAST(Ctx);
  checkRegistrationFlow(Index, D, Refs.Main);
  if (!M.Sim.CallsStart)
    D.report(DiagId::MissingStart, Refs.Main->getLocation());
  if (D.hasErrors())
    return std::nullopt;
  return M;
}

} // namespace wash::tr
