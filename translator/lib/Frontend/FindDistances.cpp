//===- FindDistances.cpp --------------------------------------------------===//
#include "wash/translator/Frontend/FindDistances.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/ParentMapContext.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Lex/Lexer.h"

#include <map>
#include <optional>

using namespace clang;

namespace wash::tr {
namespace {

const CXXRecordDecl *recordOf(QualType T) {
  return T.isNull() ? nullptr : T.getNonReferenceType().getCanonicalType()->getAsCXXRecordDecl();
}

/// wash::Particle itself, by value or reference (not a pointer, not a list).
bool isParticle(QualType T) {
  const CXXRecordDecl *RD = recordOf(T);
  return RD && !isa<ClassTemplateSpecializationDecl>(RD) && involvesParticle(T);
}

/// std::vector<wash::Particle>, by value or reference: the neighbour list.
bool isParticleList(QualType T) {
  const auto *Spec = dyn_cast_or_null<ClassTemplateSpecializationDecl>(recordOf(T));
  return Spec && Spec->getName() == "vector" && involvesParticle(T);
}

bool isVecMagnitude(const CXXMemberCallExpr *MC) {
  const CXXMethodDecl *MD = MC->getMethodDecl();
  return MD && MD->getIdentifier() && MD->getName() == "magnitude" && MC->getNumArgs() == 0 &&
         vecDimension(MC->getImplicitObjectArgument()->getType());
}

const Expr *strip(const Expr *E) { return peel(E); }

/// One end of an offset: a neighbour's position or the particle's.
struct End {
  const ParmVarDecl *List = nullptr; ///< Set for a neighbour, with its text.
  std::string Neighbour;
  const ParmVarDecl *Self = nullptr; ///< Set for the particle.
};

class FunctionScan : public RecursiveASTVisitor<FunctionScan> {
public:
  FunctionScan(ASTContext &Ctx, const Diagnoser &D, const FunctionDecl *F,
               std::vector<DistanceUse> &Found)
      : Ctx(Ctx), D(D), F(F), Found(Found) {}

  // A lambda may copy the neighbour it is given: its body is left alone.
  bool TraverseLambdaExpr(LambdaExpr *) { return true; }

  bool VisitCXXForRangeStmt(CXXForRangeStmt *S) {
    const VarDecl *V = S->getLoopVariable();
    if (V && V->getType()->isReferenceType())
      if (const ParmVarDecl *L = listParam(S->getRangeInit()))
        LoopVars[V] = L;
    return true;
  }

  bool VisitCXXMemberCallExpr(CXXMemberCallExpr *MC) {
    if (!isVecMagnitude(MC) || MC->getBeginLoc().isMacroID())
      return true;
    bool ViaLocal = false;
    const auto *Offset = dyn_cast<CXXOperatorCallExpr>(
        strip(throughLocals(MC->getImplicitObjectArgument(), ViaLocal)));
    if (!Offset || Offset->getOperator() != OO_Minus || Offset->getNumArgs() != 2)
      return true;
    std::optional<End> A = endOf(Offset->getArg(0), ViaLocal),
                       B = endOf(Offset->getArg(1), ViaLocal);
    if (!A || !B)
      return true;
    const End &N = A->List ? *A : *B, &S = A->List ? *B : *A;
    if (!N.List || !S.Self)
      return true;
    DistanceUse U;
    U.Call = D.toPos(MC->getBeginLoc());
    U.Function = F->getNameAsString();
    U.List = N.List->getNameAsString();
    U.Neighbour = N.Neighbour;
    U.Self = S.Self->getNameAsString();
    U.SelfAlways = S.Self->getType()->isLValueReferenceType() &&
                   !S.Self->getType().getNonReferenceType().isConstQualified();
    Found.push_back(U);
    return true;
  }

private:
  const ParmVarDecl *param(const Expr *E) const {
    const auto *DRE = dyn_cast_or_null<DeclRefExpr>(strip(E));
    const auto *P = DRE ? dyn_cast<ParmVarDecl>(DRE->getDecl()) : nullptr;
    return P && P->getDeclContext() == F ? P : nullptr;
  }
  const ParmVarDecl *listParam(const Expr *E) const {
    const ParmVarDecl *P = param(E);
    return P && isParticleList(P->getType()) ? P : nullptr;
  }

  /// A local variable's initialiser in place of the variable, as long as
  /// the variable is automatic and never modified (Via is set if so).
  const Expr *throughLocals(const Expr *E, bool &Via) {
    for (unsigned Depth = 0; Depth < 8; ++Depth) {
      const auto *DRE = dyn_cast<DeclRefExpr>(strip(E));
      const auto *V = DRE ? dyn_cast<VarDecl>(DRE->getDecl()) : nullptr;
      if (!V || isa<ParmVarDecl>(V) || V->getDeclContext() != F || !V->hasLocalStorage() ||
          !V->getInit() || LoopVars.count(V) ||
          (V->getType()->isReferenceType() && !isConstRef(V->getType())) || !neverModified(V))
        return E;
      E = V->getInit();
      Via = true;
    }
    return E;
  }

  /// `x.get_pos()` with x the particle parameter or an element of the list.
  std::optional<End> endOf(const Expr *E, bool ViaLocal) {
    const auto *Get = dyn_cast<CXXMemberCallExpr>(strip(throughLocals(E, ViaLocal)));
    auto Accessor = Get ? particleAccessor(Get->getMethodDecl()) : std::nullopt;
    if (!Accessor || !Accessor->reads("pos"))
      return std::nullopt;
    const Expr *Object = strip(Get->getImplicitObjectArgument());
    End Result;
    if (const ParmVarDecl *P = param(Object); P && isParticle(P->getType())) {
      Result.Self = P;
      return neverReassigned(P) ? std::optional(Result) : std::nullopt;
    }
    if (const auto *DRE = dyn_cast<DeclRefExpr>(Object)) {
      const auto *V = dyn_cast<VarDecl>(DRE->getDecl());
      if (auto It = LoopVars.find(V); It != LoopVars.end()) { // for (auto &n : ns)
        Result.List = It->second;
      } else if (V && V->getDeclContext() == F && V->hasLocalStorage() &&
                 V->getType()->isReferenceType() && V->getInit()) {
        Result.List = subscriptedList(V->getInit()); // const Particle &n = ns[k];
      }
      Result.Neighbour = DRE->getDecl()->getNameAsString();
    } else if (!ViaLocal) { // ns[k] right in the offset: k is the same at both ends
      Result.List = subscriptedList(Object);
      Result.Neighbour =
          Lexer::getSourceText(CharSourceRange::getTokenRange(Object->getSourceRange()),
                               Ctx.getSourceManager(), Ctx.getLangOpts())
              .str();
    }
    return Result.List ? std::optional(Result) : std::nullopt;
  }

  /// L for `L[k]`, L the list parameter and k a variable or a literal.
  const ParmVarDecl *subscriptedList(const Expr *E) const {
    const auto *Op = dyn_cast<CXXOperatorCallExpr>(strip(E));
    if (!Op || Op->getOperator() != OO_Subscript || Op->getNumArgs() != 2 ||
        Op->getBeginLoc().isMacroID())
      return nullptr;
    const Expr *K = Op->getArg(1)->IgnoreParenImpCasts();
    if (!isa<DeclRefExpr>(K) && !isa<IntegerLiteral>(K))
      return nullptr;
    return listParam(Op->getArg(0));
  }

  static bool isConstRef(QualType T) {
    return T->isReferenceType() && T.getNonReferenceType().isConstQualified();
  }

  bool neverModified(const VarDecl *V) { return onlyRead(V, F->getBody()); }

  /// The particle parameter is never assigned another particle.
  bool neverReassigned(const ParmVarDecl *P) {
    bool Kept = true;
    forEachUse(P, [&](const DeclRefExpr *Use) {
      auto Parents = Ctx.getParents(*Use);
      const auto *Op = Parents.size() == 1 ? Parents[0].get<CXXOperatorCallExpr>() : nullptr;
      const auto *Bin = Parents.size() == 1 ? Parents[0].get<BinaryOperator>() : nullptr;
      if ((Op && Op->getOperator() == OO_Equal && Op->getArg(0) == Use) ||
          (Bin && Bin->isAssignmentOp()))
        Kept = false;
    });
    return Kept;
  }

  template <typename Fn> void forEachUse(const ValueDecl *V, Fn Each) {
    struct Uses : RecursiveASTVisitor<Uses> { // lambda bodies included
      const ValueDecl *V;
      Fn &Each;
      Uses(const ValueDecl *V, Fn &Each) : V(V), Each(Each) {}
      bool VisitDeclRefExpr(DeclRefExpr *E) {
        if (E->getDecl() == V)
          Each(E);
        return true;
      }
    } Finder(V, Each);
    Finder.TraverseStmt(F->getBody());
  }

  ASTContext &Ctx;
  const Diagnoser &D;
  const FunctionDecl *F;
  std::vector<DistanceUse> &Found;
  std::map<const VarDecl *, const ParmVarDecl *> LoopVars;
};

class Functions : public RecursiveASTVisitor<Functions> {
public:
  Functions(ASTContext &Ctx, const Diagnoser &D, std::vector<DistanceUse> &Found)
      : Ctx(Ctx), D(D), Found(Found) {}

  bool VisitFunctionDecl(FunctionDecl *F) {
    const auto *Method = dyn_cast<CXXMethodDecl>(F);
    if (!F->doesThisDeclarationHaveABody() || (Method && Method->getParent()->isLambda()) ||
        !isUserCode(Ctx.getSourceManager(), F))
      return true;
    bool HasList = false, HasParticle = false;
    for (const ParmVarDecl *P : F->parameters()) {
      HasList |= isParticleList(P->getType());
      HasParticle |= isParticle(P->getType());
    }
    if (HasList && HasParticle) {
      FunctionScan Scan(Ctx, D, F, Found);
      Scan.TraverseStmt(F->getBody());
    }
    return true;
  }

private:
  ASTContext &Ctx;
  const Diagnoser &D;
  std::vector<DistanceUse> &Found;
};

} // namespace

std::vector<DistanceUse> findNeighbourDistances(ASTContext &Ctx, const Diagnoser &D) {
  std::vector<DistanceUse> Found;
  Functions Finder(Ctx, D, Found);
  Finder.TraverseDecl(Ctx.getTranslationUnitDecl());
  return Found;
}

} // namespace wash::tr
