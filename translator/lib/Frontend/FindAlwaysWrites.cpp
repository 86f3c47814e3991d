//===- FindAlwaysWrites.cpp -----------------------------------------------===//
#include "wash/translator/Frontend/FindAlwaysWrites.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ExprCXX.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/AST/StmtCXX.h"

#include <map>

using namespace clang;

namespace wash::tr {
namespace {

/// The jumps in S that end a straight path: returns of the function itself
/// (a lambda's are its own), and gotos anywhere.
struct Jumps {
  bool Returns = false, Gotos = false;
};
Jumps jumpsIn(const Stmt *S) {
  struct Finder : RecursiveASTVisitor<Finder> {
    Jumps Found;
    unsigned InLambda = 0;
    bool TraverseLambdaExpr(LambdaExpr *L) {
      ++InLambda;
      bool Continue = RecursiveASTVisitor::TraverseLambdaExpr(L);
      --InLambda;
      return Continue;
    }
    bool VisitReturnStmt(ReturnStmt *) { return returned(); }
    bool VisitCoreturnStmt(CoreturnStmt *) { return returned(); }
    bool returned() {
      Found.Returns |= InLambda == 0;
      return true;
    }
    bool VisitGotoStmt(GotoStmt *) { return !(Found.Gotos = true); }
    bool VisitIndirectGotoStmt(IndirectGotoStmt *) { return !(Found.Gotos = true); }
  } F;
  F.TraverseStmt(const_cast<Stmt *>(S));
  return F.Found;
}

class AlwaysWrites {
public:
  explicit AlwaysWrites(ProgramIndex &Index) : Ctx(Index.context()), Index(Index), Walk(Index) {}

  /// The fields function FD sets on every path on the particle its parameter
  /// Self is bound to.
  FieldSet of(const FunctionDecl *FD, unsigned Self) {
    FieldSet Out;
    const FunctionDecl *Def = FD ? FD->getDefinition() : nullptr;
    if (!Def || !Def->hasBody() || Self >= Def->getNumParams() || !Index.isUserFunction(Def))
      return Out;
    auto Key = std::make_pair(Def, Self);
    if (auto It = Memo.find(Key); It != Memo.end())
      return It->second;
    // Recursion (reported elsewhere) and a spent budget count nothing.
    Walk.enter(Def, [&] {
      if (!jumpsIn(Def->getBody()).Gotos)
        block(Def->getBody(), Def->getParamDecl(Self), Out);
    });
    return Memo[Key] = Out;
  }

private:
  /// The statements of a block in order, up to the first that may return (the
  /// function has no goto).
  void block(const Stmt *S, const ParmVarDecl *Self, FieldSet &Out) {
    const auto *Block = dyn_cast<CompoundStmt>(S);
    if (!Block)
      return statement(S, Self, Out);
    for (const Stmt *Child : Block->body()) {
      if (jumpsIn(Child).Returns)
        return;
      statement(Child, Self, Out);
    }
  }

  void statement(const Stmt *S, const ParmVarDecl *Self, FieldSet &Out) {
    if (isa<CompoundStmt>(S))
      return block(S, Self, Out);
    const auto *E = dyn_cast<Expr>(S);
    if (!E)
      return; // if, loops, declarations...: nothing counts as always done
    E = E->IgnoreImplicit();
    if (const auto *Cast = dyn_cast<CStyleCastExpr>(E); Cast && Cast->getType()->isVoidType())
      E = Cast->getSubExpr()->IgnoreImplicit();
    const auto *Call = dyn_cast<CallExpr>(E);
    if (!Call || !Call->getDirectCallee())
      return;
    const FunctionDecl *Callee = Call->getDirectCallee();
    if (isParticleMethod(Callee)) {
      const auto *Member = dyn_cast<CXXMemberCallExpr>(Call);
      if (Member && isSelf(Member->getImplicitObjectArgument(), Self))
        if (auto Field = setterField(Member))
          Out.insert(*Field);
      return;
    }
    unsigned Skip = isa<CXXOperatorCallExpr>(Call) && isa<CXXMethodDecl>(Callee) ? 1 : 0;
    for (unsigned I = Skip; I < Call->getNumArgs(); ++I)
      if (isSelf(Call->getArg(I), Self) && I - Skip < Callee->getNumParams() &&
          Callee->getParamDecl(I - Skip)->getType()->isReferenceType()) {
        FieldSet Inner = of(Callee, I - Skip);
        Out.insert(Inner.begin(), Inner.end());
      }
  }

  static bool isSelf(const Expr *E, const ParmVarDecl *Self) {
    const auto *DRE = dyn_cast<DeclRefExpr>(E->IgnoreParenImpCasts());
    return DRE && DRE->getDecl() == Self;
  }

  /// The field a setter call sets: a builtin's, or a force by constant name.
  std::optional<std::string> setterField(const CXXMemberCallExpr *Call) {
    auto A = particleAccessor(Call->getMethodDecl());
    if (!A || A->How != Mode::Write)
      return std::nullopt;
    if (A->IsType)
      return std::string(TypeField);
    if (A->isForce())
      return Call->getNumArgs() ? evaluateString(Call->getArg(0), Ctx) : std::nullopt;
    return A->Field->Name;
  }

  ASTContext &Ctx;
  ProgramIndex &Index;
  CallWalk<> Walk;
  std::map<std::pair<const FunctionDecl *, unsigned>, FieldSet> Memo;
};

} // namespace

std::vector<FieldSet> findAlwaysWrites(ProgramIndex &Index, const AstRefs &Refs,
                                       const std::vector<Kernel> &Kernels) {
  AlwaysWrites Finder(Index);
  std::vector<FieldSet> Out(Kernels.size());
  for (unsigned I = 0; I < Kernels.size(); ++I)
    if (Kernels[I].Kind == KernelKind::Update || Kernels[I].Kind == KernelKind::Force)
      Out[I] = Finder.of(Refs.Kernels[I], 0);
  return Out;
}

} // namespace wash::tr
