//===- FindHoistable.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/FindHoistable.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/PureFunctions.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ParentMapContext.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Lex/Lexer.h"

#include <algorithm>
#include <map>
#include <set>

using namespace clang;

namespace wash::tr {
namespace {

const FunctionDecl *canonical(const FunctionDecl *FD) {
  return FD ? FD->getCanonicalDecl() : nullptr;
}

/// A name the driver, at namespace scope after the user's code, can use.
std::string globalName(const NamedDecl *ND) {
  std::string Name = ND->getQualifiedNameAsString();
  const std::string Anonymous = "(anonymous namespace)::";
  for (size_t At; (At = Name.find(Anonymous)) != std::string::npos;)
    Name.erase(At, Anonymous.size());
  return "::" + Name;
}

bool isDouble(QualType T) {
  return !T.isNull() &&
         T.getCanonicalType().getUnqualifiedType()->isSpecificBuiltinType(BuiltinType::Double);
}

/// For each function, the force kernels whose calls reach it; none when
/// anything else may run it (main, another kind of kernel, a lambda, an
/// initialiser, a caller through its address).
class KernelReach {
public:
  KernelReach(const ProgramIndex &Index, const AstRefs &Refs, const std::vector<Kernel> &Kernels) {
    std::vector<const FunctionDecl *> Others(Index.runAnywhere().begin(),
                                             Index.runAnywhere().end());
    std::vector<unsigned> Forces;
    for (unsigned K = 0; K < Kernels.size() && K < Refs.Kernels.size(); ++K)
      if (Refs.Kernels[K])
        Kernels[K].Kind == KernelKind::Force ? Forces.push_back(K)
                                             : Others.push_back(Refs.Kernels[K]);
    Others.push_back(Refs.Main);
    Unsafe = Index.reachableFrom(Others);
    for (unsigned K : Forces)
      for (const FunctionDecl *F : Index.reachableFrom({Refs.Kernels[K]}))
        ReachedBy[F].push_back(K);
  }

  std::vector<unsigned> kernelsReaching(const FunctionDecl *F) const {
    F = canonical(F);
    auto It = ReachedBy.find(F);
    if (Unsafe.count(F) || It == ReachedBy.end())
      return {};
    return It->second;
  }

private:
  std::set<const FunctionDecl *> Unsafe;
  std::map<const FunctionDecl *, std::vector<unsigned>> ReachedBy;
};

/// The text of an expression over one neighbour, for any row: what
/// findHoistable keeps. Fails on anything it cannot show to be such.
class Printer {
public:
  Printer(ASTContext &Ctx, const FunctionDecl *F, const std::set<const VarDecl *> &LoopVars,
          const ProgramIndex &Index, Purity &Pure)
      : Ctx(Ctx), F(F), LoopVars(LoopVars), Index(Index), Pure(Pure) {}

  std::vector<HoistPiece> Pieces;
  FieldSet Reads;
  const VarDecl *Neighbour = nullptr;
  bool Worth = false; ///< A call or a division, as written (not through locals).

  bool print(const Expr *E, bool Written = true, unsigned Depth = 0) {
    if (!E || Depth > 64 || E->getBeginLoc().isMacroID() || E->getEndLoc().isMacroID())
      return false;
    // Every operator below parenthesises itself: the user's parentheses need not.
    if (const auto *P = dyn_cast<ParenExpr>(E))
      return print(P->getSubExpr(), Written, Depth + 1);
    if (isa<MaterializeTemporaryExpr, ConstantExpr, FullExpr>(E))
      return print(cast<Expr>(*E->child_begin()), Written, Depth + 1);
    if (const auto *Cast = dyn_cast<ImplicitCastExpr>(E)) {
      // The same conversion happens again: the operands have the same types.
      if (Cast->getCastKind() == CK_FloatingToIntegral ||
          !isArithmetic(Cast->getSubExpr()->getType()) || !isArithmetic(Cast->getType()))
        return false;
      return print(Cast->getSubExpr(), Written, Depth + 1);
    }
    if (const auto *Cast = dyn_cast<ExplicitCastExpr>(E)) {
      if (Cast->getCastKind() == CK_FloatingToIntegral || !isArithmetic(Cast->getType()) ||
          !isArithmetic(Cast->getSubExprAsWritten()->getType()))
        return false;
      return text("static_cast<" + typeName(Cast->getType()) + ">(") &&
             print(Cast->getSubExprAsWritten(), Written, Depth + 1) && text(")");
    }
    if (isa<IntegerLiteral, FloatingLiteral, CXXBoolLiteralExpr>(E))
      return text(source(E));
    if (const auto *Un = dyn_cast<UnaryOperator>(E)) {
      UnaryOperatorKind Op = Un->getOpcode();
      if (Op != UO_Minus && Op != UO_Plus && Op != UO_LNot)
        return false;
      return text(std::string(UnaryOperator::getOpcodeStr(Op)) + "(") &&
             print(Un->getSubExpr(), Written, Depth + 1) && text(")");
    }
    if (const auto *Bin = dyn_cast<BinaryOperator>(E)) {
      if (Bin->isAssignmentOp() || !Purity::binaryAllowed(Bin))
        return false;
      Worth |= Written && Bin->getOpcode() == BO_Div;
      return text("(") && print(Bin->getLHS(), Written, Depth + 1) &&
             text(" " + Bin->getOpcodeStr().str() + " ") &&
             print(Bin->getRHS(), Written, Depth + 1) && text(")");
    }
    if (const auto *Cond = dyn_cast<ConditionalOperator>(E))
      return text("(") && print(Cond->getCond(), Written, Depth + 1) && text(" ? ") &&
             print(Cond->getTrueExpr(), Written, Depth + 1) && text(" : ") &&
             print(Cond->getFalseExpr(), Written, Depth + 1) && text(")");
    if (const auto *MC = dyn_cast<CXXMemberCallExpr>(E))
      return neighbourRead(MC);
    if (const auto *Call = dyn_cast<CallExpr>(E))
      return call(Call, Written, Depth);
    if (const auto *Member = dyn_cast<MemberExpr>(E))
      return member(Member);
    if (const auto *Ref = dyn_cast<DeclRefExpr>(E))
      return reference(Ref, Depth);
    return false;
  }

private:
  bool text(const std::string &T) {
    if (!Pieces.empty() && !Pieces.back().isRead())
      Pieces.back().Text += T;
    else
      Pieces.push_back({T, "", ForceKind::Scalar});
    return true;
  }

  std::string source(const Expr *E) const {
    return Lexer::getSourceText(CharSourceRange::getTokenRange(E->getSourceRange()),
                                Ctx.getSourceManager(), Ctx.getLangOpts())
        .str();
  }

  std::string typeName(QualType T) const {
    return T.getCanonicalType().getUnqualifiedType().getAsString(Ctx.getPrintingPolicy());
  }

  /// A scalar getter on the loop variable.
  bool neighbourRead(const CXXMemberCallExpr *MC) {
    auto Accessor = particleAccessor(MC->getMethodDecl());
    if (!Accessor || Accessor->How != Mode::Read || Accessor->IsType ||
        Accessor->Kind != ForceKind::Scalar || (Accessor->Field && Accessor->Field->Name == "id"))
      return false;
    const auto *Object =
        dyn_cast<DeclRefExpr>(MC->getImplicitObjectArgument()->IgnoreParenImpCasts());
    const auto *V = Object ? dyn_cast<VarDecl>(Object->getDecl()) : nullptr;
    if (!V || !LoopVars.count(V) || (Neighbour && Neighbour != V))
      return false;
    std::string Field;
    if (Accessor->Field) {
      Field = Accessor->Field->Name;
    } else {
      auto Name = MC->getNumArgs() ? evaluateString(MC->getArg(0), Ctx) : std::nullopt;
      if (!Name)
        return false;
      Field = *Name;
    }
    Neighbour = V;
    Reads.insert(Field);
    Pieces.push_back({"", Field, ForceKind::Scalar});
    return true;
  }

  bool call(const CallExpr *Call, bool Written, unsigned Depth) {
    const FunctionDecl *Callee = Call->getDirectCallee();
    if (isa<CXXOperatorCallExpr>(Call) || !Callee || Callee->isVariadic() ||
        Callee->getNumParams() != Call->getNumArgs() || !Pure.pure(Callee) ||
        Callee->getTemplatedKind() != FunctionDecl::TK_NonTemplate ||
        !isArithmetic(Call->getType()) || Call->getType()->isReferenceType())
      return false;
    for (const ParmVarDecl *P : Callee->parameters())
      if (!isArithmetic(P->getType()) || !Purity::parameterReadOnly(P->getType()))
        return false;
    Worth |= Written;
    text(globalName(Callee) + "(");
    for (unsigned I = 0; I < Call->getNumArgs(); ++I)
      if ((I && !text(", ")) || isa<CXXDefaultArgExpr>(Call->getArg(I)) ||
          !print(Call->getArg(I), Written, Depth + 1))
        return false;
    return text(")");
  }

  /// A constant object's field: `scheme.gamma`, or `s.gamma` with `s` a
  /// parameter every call binds to the same constant.
  bool member(const MemberExpr *Member) {
    const auto *Field = dyn_cast<FieldDecl>(Member->getMemberDecl());
    const auto *Base = dyn_cast<DeclRefExpr>(Member->getBase()->IgnoreParenImpCasts());
    if (Member->isArrow() || !Field || Field->isMutable() || !Base ||
        !isArithmetic(Member->getType()))
      return false;
    std::optional<std::string> Object = constant(Base->getDecl());
    return Object && text(*Object + "." + Field->getNameAsString());
  }

  bool reference(const DeclRefExpr *Ref, unsigned Depth) {
    const ValueDecl *D = Ref->getDecl();
    if (!isArithmetic(D->getType()))
      return false;
    if (isa<EnumConstantDecl>(D))
      return text(globalName(D));
    const auto *V = dyn_cast<VarDecl>(D);
    if (!V)
      return false;
    if (std::optional<std::string> Constant = constant(V))
      return text(*Constant);
    // A local never modified: its initialiser, converted to its type.
    if (isa<ParmVarDecl>(V) || !V->hasLocalStorage() || V->getDeclContext() != F || !V->getInit() ||
        V->getType()->isReferenceType() || V->isCXXForRangeDecl() || LoopVars.count(V) ||
        !onlyRead(V, F->getBody()))
      return false;
    const Expr *Init = V->getInit();
    bool Same = typeName(Init->IgnoreImpCasts()->getType()) == typeName(V->getType()) &&
                typeName(Init->getType()) == typeName(V->getType());
    if (Same)
      return print(Init, false, Depth + 1);
    return text("static_cast<" + typeName(V->getType()) + ">(") && print(Init, false, Depth + 1) &&
           text(")");
  }

  /// The text of a constant V: a const namespace-scope variable, or a
  /// parameter of F that every call binds to the same one.
  std::optional<std::string> constant(const ValueDecl *D) {
    const auto *V = dyn_cast<VarDecl>(D);
    if (!V)
      return std::nullopt;
    if (V->isFileVarDecl()) {
      QualType T = V->getType();
      if (!T.isConstQualified() || T.isVolatileQualified() || T->isReferenceType() ||
          V->getDescribedVarTemplate() || isa<VarTemplateSpecializationDecl>(V))
        return std::nullopt;
      return globalName(V);
    }
    const auto *P = dyn_cast<ParmVarDecl>(V);
    if (!P || P->getDeclContext() != F || !Purity::parameterReadOnly(P->getType()))
      return std::nullopt;
    const auto &Calls = Index.callsOf(F);
    const VarDecl *Bound = nullptr;
    for (const CallExpr *Call : Calls) {
      unsigned I = P->getFunctionScopeIndex();
      if (I >= Call->getNumArgs())
        return std::nullopt;
      const auto *Arg = dyn_cast<DeclRefExpr>(Call->getArg(I)->IgnoreParenImpCasts());
      const auto *G = Arg ? dyn_cast<VarDecl>(Arg->getDecl()) : nullptr;
      if (!G || (Bound && G != Bound) || !G->isFileVarDecl() ||
          typeName(G->getType()) != typeName(P->getType().getNonReferenceType()))
        return std::nullopt;
      Bound = G;
    }
    if (!Bound)
      return std::nullopt;
    return constant(Bound);
  }

  ASTContext &Ctx;
  const FunctionDecl *F;
  const std::set<const VarDecl *> &LoopVars;
  const ProgramIndex &Index;
  Purity &Pure;
};

/// The largest hoistable expressions in one function's neighbour loops.
class FunctionScan : public RecursiveASTVisitor<FunctionScan> {
public:
  FunctionScan(ASTContext &Ctx, const Diagnoser &D, const FunctionDecl *F,
               std::vector<unsigned> Kernels, const ProgramIndex &Index, Purity &Pure,
               std::vector<HoistedExpr> &Found)
      : Ctx(Ctx), D(D), F(F), Kernels(std::move(Kernels)), Index(Index), Pure(Pure), Found(Found) {}

  void run() {
    struct Loops : RecursiveASTVisitor<Loops> {
      const FunctionDecl *F;
      std::set<const VarDecl *> Vars;
      bool TraverseLambdaExpr(LambdaExpr *) { return true; }
      bool VisitCXXForRangeStmt(CXXForRangeStmt *S) {
        const VarDecl *V = S->getLoopVariable();
        const auto *Range = dyn_cast<DeclRefExpr>(S->getRangeInit()->IgnoreParenImpCasts());
        const auto *P = Range ? dyn_cast<ParmVarDecl>(Range->getDecl()) : nullptr;
        if (V && V->getType()->isReferenceType() && P && P->getDeclContext() == F &&
            involvesParticle(P->getType()) && !P->getType()->isPointerType())
          Vars.insert(V);
        return true;
      }
    } Finder;
    Finder.F = F;
    Finder.TraverseStmt(F->getBody());
    LoopVars = std::move(Finder.Vars);
    if (!LoopVars.empty())
      TraverseStmt(F->getBody());
  }

  bool TraverseLambdaExpr(LambdaExpr *) { return true; }

  bool TraverseStmt(Stmt *S) {
    const auto *E = dyn_cast_or_null<Expr>(S);
    if (!E || isa<ImplicitCastExpr, MaterializeTemporaryExpr, FullExpr, ConstantExpr>(E) ||
        !isDouble(E->getType()) || E->isGLValue())
      return RecursiveASTVisitor::TraverseStmt(S);
    Printer P(Ctx, F, LoopVars, Index, Pure);
    if (!P.print(E) || !P.Neighbour || !P.Worth)
      return RecursiveASTVisitor::TraverseStmt(S);
    HoistedExpr H;
    H.Begin = D.toPos(E->getBeginLoc());
    H.End = D.toPos(E->getEndLoc());
    H.Function = F->getNameAsString();
    H.Neighbour = P.Neighbour->getNameAsString();
    H.Written = oneLine(Lexer::getSourceText(CharSourceRange::getTokenRange(E->getSourceRange()),
                                             Ctx.getSourceManager(), Ctx.getLangOpts())
                            .str());
    H.Compute = std::move(P.Pieces);
    H.Reads = std::move(P.Reads);
    H.Kernels = Kernels;
    Found.push_back(std::move(H));
    return true; // the largest only
  }

private:
  static std::string oneLine(const std::string &S) {
    std::string Out;
    for (char C : S) {
      bool Space = C == ' ' || C == '\n' || C == '\t' || C == '\r';
      if (Space && (Out.empty() || Out.back() == ' '))
        continue;
      Out += Space ? ' ' : C;
    }
    return Out;
  }

  ASTContext &Ctx;
  const Diagnoser &D;
  const FunctionDecl *F;
  std::vector<unsigned> Kernels;
  const ProgramIndex &Index;
  Purity &Pure;
  std::vector<HoistedExpr> &Found;
  std::set<const VarDecl *> LoopVars;
};

} // namespace

std::vector<HoistedExpr> findHoistable(const ProgramIndex &Index, const Diagnoser &D,
                                       const AstRefs &Refs, const std::vector<Kernel> &Kernels) {
  ASTContext &Ctx = Index.context();
  std::vector<HoistedExpr> Found;
  KernelReach Graph(Index, Refs, Kernels);
  Purity Pure(Ctx.getSourceManager());
  // Every function with a body once, in source order.
  struct Functions : RecursiveASTVisitor<Functions> {
    const SourceManager &SM;
    std::vector<const FunctionDecl *> All;
    explicit Functions(const SourceManager &SM) : SM(SM) {}
    bool VisitFunctionDecl(FunctionDecl *FD) {
      if (FD->doesThisDeclarationHaveABody() && !isa<CXXMethodDecl>(FD) &&
          FD->getTemplatedKind() == FunctionDecl::TK_NonTemplate && isUserCode(SM, FD))
        All.push_back(FD);
      return true;
    }
  } Finder(Ctx.getSourceManager());
  Finder.TraverseDecl(Ctx.getTranslationUnitDecl());
  for (const FunctionDecl *F : Finder.All) {
    std::vector<unsigned> Reaching = Graph.kernelsReaching(F);
    if (Reaching.empty() || F->getLocation().isMacroID())
      continue;
    FunctionScan Scan(Ctx, D, F, std::move(Reaching), Index, Pure, Found);
    Scan.run();
  }
  return Found;
}

} // namespace wash::tr
