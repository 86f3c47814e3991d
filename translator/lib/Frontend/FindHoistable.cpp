//===- FindHoistable.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/FindHoistable.h"
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

/// Who calls whom among the user's functions, and which functions some code
/// other than a force kernel's calls may run (main, another kind of kernel, a
/// lambda, an initialiser, a function whose address is taken).
class CallGraph : public RecursiveASTVisitor<CallGraph> {
public:
  CallGraph(ASTContext &Ctx, const AstRefs &Refs, const std::vector<Kernel> &Kernels) : Ctx(Ctx) {
    for (unsigned K = 0; K < Kernels.size(); ++K)
      if (K < Refs.Kernels.size() && Refs.Kernels[K])
        (Kernels[K].Kind == KernelKind::Force ? ForceKernels : OtherRoots)
            .insert(canonical(Refs.Kernels[K]));
    if (Refs.Main)
      OtherRoots.insert(canonical(Refs.Main));
  }

  bool shouldVisitTemplateInstantiations() const { return true; }
  bool shouldVisitImplicitCode() const { return true; }

  bool TraverseFunctionDecl(FunctionDecl *FD) { return traverseFunction(FD); }
  bool TraverseCXXMethodDecl(CXXMethodDecl *FD) {
    Stack.push_back(
        nullptr); // members (a lambda's too) are not followed: their calls may run anywhere
    bool Result = RecursiveASTVisitor::TraverseCXXMethodDecl(FD);
    Stack.pop_back();
    return Result;
  }
  bool TraverseLambdaExpr(LambdaExpr *L) {
    Stack.push_back(nullptr); // a lambda may run anywhere
    bool Result = RecursiveASTVisitor::TraverseLambdaExpr(L);
    Stack.pop_back();
    return Result;
  }

  bool VisitCallExpr(CallExpr *E) {
    const FunctionDecl *Callee = canonical(E->getDirectCallee());
    if (!Callee)
      return true;
    CalleeRefs.insert(E->getCallee()->IgnoreParenImpCasts());
    const FunctionDecl *Caller = Stack.empty() ? nullptr : Stack.back();
    if (!Caller || OtherRoots.count(Caller))
      Unsafe.insert(Callee);
    else
      Callees[Caller].insert(Callee);
    CallSites[Callee].push_back(E);
    return true;
  }

  bool VisitDeclRefExpr(DeclRefExpr *E) {
    if (const auto *FD = dyn_cast<FunctionDecl>(E->getDecl()))
      FunctionRefs.push_back(E);
    return true;
  }

  bool VisitOverloadExpr(OverloadExpr *E) { // names resolved only later
    for (const NamedDecl *ND : E->decls())
      if (const auto *FD = dyn_cast<FunctionDecl>(ND->getUnderlyingDecl()))
        Unsafe.insert(canonical(FD));
    return true;
  }

  /// Finishes the graph: the functions unsafe code reaches, and for each
  /// function the force kernels whose calls reach it.
  void close(const std::vector<const FunctionDecl *> &Kernels) {
    for (const DeclRefExpr *Ref : FunctionRefs)
      if (!CalleeRefs.count(Ref) && !inRegistration(Ref))
        Unsafe.insert(canonical(cast<FunctionDecl>(Ref->getDecl())));
    for (const FunctionDecl *Root : OtherRoots)
      Unsafe.insert(Root);
    std::vector<const FunctionDecl *> Work(Unsafe.begin(), Unsafe.end());
    while (!Work.empty()) {
      const FunctionDecl *F = Work.back();
      Work.pop_back();
      for (const FunctionDecl *C : Callees[F])
        if (Unsafe.insert(C).second)
          Work.push_back(C);
    }
    for (unsigned K = 0; K < Kernels.size(); ++K) {
      const FunctionDecl *Root = canonical(Kernels[K]);
      if (!Root || !ForceKernels.count(Root))
        continue;
      std::set<const FunctionDecl *> Seen = {Root};
      std::vector<const FunctionDecl *> Todo = {Root};
      while (!Todo.empty()) {
        const FunctionDecl *F = Todo.back();
        Todo.pop_back();
        ReachedBy[F].push_back(K);
        for (const FunctionDecl *C : Callees[F])
          if (Seen.insert(C).second)
            Todo.push_back(C);
      }
    }
  }

  /// The force kernels reaching F, none if anything else may run it.
  std::vector<unsigned> kernelsReaching(const FunctionDecl *F) const {
    F = canonical(F);
    auto It = ReachedBy.find(F);
    if (Unsafe.count(F) || It == ReachedBy.end())
      return {};
    return It->second;
  }

  const std::vector<const CallExpr *> &callsOf(const FunctionDecl *F) {
    return CallSites[canonical(F)];
  }

private:
  bool traverseFunction(FunctionDecl *FD) {
    Stack.push_back(canonical(FD));
    bool Result = RecursiveASTVisitor::TraverseFunctionDecl(FD);
    Stack.pop_back();
    return Result;
  }

  /// A kernel's function named in the call that registers it.
  bool inRegistration(const Expr *Ref) const {
    const Expr *E = Ref;
    for (unsigned Depth = 0; Depth < 6; ++Depth) {
      auto Parents = Ctx.getParents(*E);
      if (Parents.size() != 1)
        return false;
      if (const auto *Call = Parents[0].get<CallExpr>())
        return isWashFunction(Call->getDirectCallee());
      const auto *Up = Parents[0].get<Expr>();
      if (!Up || !(isa<ImplicitCastExpr>(Up) || isa<ParenExpr>(Up) || isa<UnaryOperator>(Up)))
        return false;
      E = Up;
    }
    return false;
  }

  ASTContext &Ctx;
  std::set<const FunctionDecl *> ForceKernels, OtherRoots, Unsafe;
  std::vector<const FunctionDecl *> Stack;
  std::map<const FunctionDecl *, std::set<const FunctionDecl *>> Callees;
  std::map<const FunctionDecl *, std::vector<const CallExpr *>> CallSites;
  std::map<const FunctionDecl *, std::vector<unsigned>> ReachedBy;
  std::set<const Expr *> CalleeRefs;
  std::vector<const DeclRefExpr *> FunctionRefs;
};

/// The text of an expression over one neighbour, for any row: what
/// findHoistable keeps. Fails on anything it cannot show to be such.
class Printer {
public:
  Printer(ASTContext &Ctx, const FunctionDecl *F, const std::set<const VarDecl *> &LoopVars,
          CallGraph &Graph, Purity &Pure)
      : Ctx(Ctx), F(F), LoopVars(LoopVars), Graph(Graph), Pure(Pure) {}

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
        !onlyRead(V))
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
    const auto &Calls = Graph.callsOf(F);
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

  /// Every use of V reads its value.
  bool onlyRead(const VarDecl *V) {
    struct Uses : RecursiveASTVisitor<Uses> {
      const VarDecl *V;
      ASTContext &Ctx;
      bool Read = true;
      Uses(const VarDecl *V, ASTContext &Ctx) : V(V), Ctx(Ctx) {}
      bool VisitDeclRefExpr(DeclRefExpr *E) {
        if (E->getDecl() != V)
          return true;
        const Expr *At = E;
        while (true) {
          auto Parents = Ctx.getParents(*At);
          const auto *Up = Parents.size() == 1 ? Parents[0].get<Expr>() : nullptr;
          if (const auto *Paren = dyn_cast_or_null<ParenExpr>(Up)) {
            At = Paren;
            continue;
          }
          const auto *Cast = dyn_cast_or_null<ImplicitCastExpr>(Up);
          Read = Read && Cast && Cast->getCastKind() == CK_LValueToRValue;
          return true;
        }
      }
    } Finder(V, Ctx);
    Finder.TraverseStmt(F->getBody());
    return Finder.Read;
  }

  ASTContext &Ctx;
  const FunctionDecl *F;
  const std::set<const VarDecl *> &LoopVars;
  CallGraph &Graph;
  Purity &Pure;
};

/// The largest hoistable expressions in one function's neighbour loops.
class FunctionScan : public RecursiveASTVisitor<FunctionScan> {
public:
  FunctionScan(ASTContext &Ctx, const Diagnoser &D, const FunctionDecl *F,
               std::vector<unsigned> Kernels, CallGraph &Graph, Purity &Pure,
               std::vector<HoistedExpr> &Found)
      : Ctx(Ctx), D(D), F(F), Kernels(std::move(Kernels)), Graph(Graph), Pure(Pure), Found(Found) {}

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
    Printer P(Ctx, F, LoopVars, Graph, Pure);
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
  CallGraph &Graph;
  Purity &Pure;
  std::vector<HoistedExpr> &Found;
  std::set<const VarDecl *> LoopVars;
};

} // namespace

std::vector<HoistedExpr> findHoistable(ASTContext &Ctx, const Diagnoser &D, const AstRefs &Refs,
                                       const std::vector<Kernel> &Kernels) {
  std::vector<HoistedExpr> Found;
  CallGraph Graph(Ctx, Refs, Kernels);
  Graph.TraverseDecl(Ctx.getTranslationUnitDecl());
  Graph.close(Refs.Kernels);
  Purity Pure(Ctx.getSourceManager());
  // Every function with a body once, in source order.
  struct Functions : RecursiveASTVisitor<Functions> {
    const SourceManager &SM;
    std::vector<const FunctionDecl *> All;
    explicit Functions(const SourceManager &SM) : SM(SM) {}
    bool VisitFunctionDecl(FunctionDecl *FD) {
      if (FD->doesThisDeclarationHaveABody() && !isa<CXXMethodDecl>(FD) &&
          FD->getTemplatedKind() == FunctionDecl::TK_NonTemplate &&
          !SM.isInSystemHeader(SM.getExpansionLoc(FD->getLocation())))
        All.push_back(FD);
      return true;
    }
  } Finder(Ctx.getSourceManager());
  Finder.TraverseDecl(Ctx.getTranslationUnitDecl());
  for (const FunctionDecl *F : Finder.All) {
    std::vector<unsigned> Reaching = Graph.kernelsReaching(F);
    if (Reaching.empty() || F->getLocation().isMacroID())
      continue;
    FunctionScan Scan(Ctx, D, F, std::move(Reaching), Graph, Pure, Found);
    Scan.run();
  }
  return Found;
}

} // namespace wash::tr
