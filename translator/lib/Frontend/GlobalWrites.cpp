//===- GlobalWrites.cpp ---------------------------------------------------===//
#include "wash/translator/Frontend/GlobalWrites.h"
#include "wash/translator/Frontend/AstQueries.h"
#include "wash/translator/Frontend/WashApi.h"
#include "wash/translator/Frontend/WriteAccess.h"

#include "clang/AST/Attr.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"

using namespace clang;

namespace wash::tr {
namespace {

constexpr unsigned MaxDepth = 64;

void merge(StorageRoots &Into, const StorageRoots &From) { Into.insert(From.begin(), From.end()); }

const Expr *strip(const Expr *E) {
  PeelOptions Through;
  Through.ExplicitCasts = Through.DefaultArguments = Through.InitializerLists = true;
  Through.IsCopy = noConstruction;
  return peel(E, Through);
}

/// The class of `this` when E, a write's target, goes through a reference
/// or pointer one of `this`'s members holds (`into = 1` for a reference
/// member, `*slot = 1`): the object then writes where it was pointed.
const CXXRecordDecl *heldThroughThis(const Expr *E, bool Through = false, unsigned Depth = 0) {
  E = strip(E);
  if (!E || Depth > MaxDepth)
    return nullptr;
  if (const auto *M = dyn_cast<MemberExpr>(E)) {
    QualType T = M->getMemberDecl()->getType();
    bool ViaMember = Through || T->isReferenceType();
    const Expr *Base = strip(M->getBase());
    if (isa<CXXThisExpr>(Base))
      return ViaMember && holdsMutablePointer(T) ? Base->getType()->getPointeeCXXRecordDecl()
                                                 : nullptr;
    return heldThroughThis(M->getBase(), ViaMember || M->isArrow(), Depth + 1);
  }
  if (const auto *A = dyn_cast<ArraySubscriptExpr>(E))
    return heldThroughThis(A->getBase(), Through || !strip(A->getBase())->getType()->isArrayType(),
                           Depth + 1);
  if (const auto *U = dyn_cast<UnaryOperator>(E); U && U->getOpcode() == UO_Deref)
    return heldThroughThis(U->getSubExpr(), true, Depth + 1);
  if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(E);
      OC && OC->getNumArgs() > 0 &&
      (OC->getOperator() == OO_Star || OC->getOperator() == OO_Subscript ||
       OC->getOperator() == OO_Arrow))
    return heldThroughThis(OC->getArg(0), Through || isShallow(OC->getDirectCallee()), Depth + 1);
  return nullptr;
}

/// The callee's name, for a diagnostic.
std::string nameOf(const FunctionDecl *FD) {
  return FD ? FD->getQualifiedNameAsString() : "a function called through a pointer";
}

/// The arguments of CE that bind FD's parameters (a member operator's
/// object is its first argument).
llvm::ArrayRef<const Expr *> boundArguments(const CallExpr *CE, const FunctionDecl *FD) {
  llvm::ArrayRef<const Expr *> Args(CE->getArgs(), CE->getNumArgs());
  if (isa<CXXOperatorCallExpr>(CE) && isa_and_nonnull<CXXMethodDecl>(FD) && !Args.empty())
    return Args.drop_front();
  return Args;
}

const Expr *implicitObject(const CallExpr *CE) {
  if (const auto *MC = dyn_cast<CXXMemberCallExpr>(CE))
    return MC->getImplicitObjectArgument();
  if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(CE);
      OC && isa_and_nonnull<CXXMethodDecl>(OC->getDirectCallee()) && OC->getNumArgs() > 0)
    return OC->getArg(0);
  return nullptr;
}

/// The parameter types a call binds, for callees with no declaration too.
std::vector<QualType> parameterTypes(const CallExpr *CE, const FunctionDecl *FD) {
  std::vector<QualType> Types;
  if (FD) {
    for (const ParmVarDecl *P : FD->parameters())
      Types.push_back(P->getType());
    return Types;
  }
  QualType T = CE->getCallee()->getType();
  if (const auto *P = T->getAs<PointerType>())
    T = P->getPointeeType();
  else if (const auto *R = T->getAs<ReferenceType>())
    T = R->getPointeeType();
  if (const auto *Proto = T->getAs<FunctionProtoType>())
    for (QualType P : Proto->param_types())
      Types.push_back(P);
  return Types;
}

} // namespace

bool SharedStateFinder::followed(const FunctionDecl *FD) const {
  const FunctionDecl *Def = FD ? FD->getDefinition() : nullptr;
  if (!Def || !Def->hasBody() || isWashFunction(FD) || isa<CXXConstructorDecl>(FD) ||
      !isUserCode(Ctx.getSourceManager(), Def))
    return false;
  // A virtual call may land in an override the walk does not follow.
  const auto *MD = dyn_cast<CXXMethodDecl>(FD);
  return !MD || !MD->isVirtual() || MD->hasAttr<FinalAttr>() ||
         MD->getParent()->hasAttr<FinalAttr>();
}

/// Where the storage the glvalue E designates lies.
StorageRoots SharedStateFinder::objectRoots(const Expr *E, unsigned Depth) {
  E = strip(E);
  if (!E || Depth > MaxDepth)
    return {};
  // Nested calls reach their arguments both ways: without the cache, the
  // work would double with every level.
  auto Key = std::make_pair(E, false);
  if (auto It = Cache.find(Key); It != Cache.end())
    return It->second;
  return Cache[Key] = objectRootsOf(E, Depth);
}

StorageRoots SharedStateFinder::objectRootsOf(const Expr *E, unsigned Depth) {
  if (const auto *DRE = dyn_cast<DeclRefExpr>(E)) {
    if (const auto *B = dyn_cast<BindingDecl>(DRE->getDecl()))
      return objectRoots(B->getBinding(), Depth + 1);
    const auto *VD = dyn_cast<VarDecl>(DRE->getDecl());
    if (!VD)
      return {};
    if (VD->hasGlobalStorage())
      return {{VD, false}};
    if (!VD->getType()->isReferenceType())
      return {{VD, false}};
    if (isa<ParmVarDecl>(VD))
      return {{VD, true}};
    // A local reference is bound once, by its initialiser.
    return VD->getInit() ? objectRoots(VD->getInit(), Depth + 1) : StorageRoots{};
  }
  if (const auto *M = dyn_cast<MemberExpr>(E)) {
    if (const auto *VD = dyn_cast<VarDecl>(M->getMemberDecl())) // A static member.
      return {{VD, false}};
    if (M->isArrow())
      return pointeeRoots(M->getBase(), Depth + 1);
    StorageRoots R = objectRoots(M->getBase(), Depth + 1);
    if (M->getMemberDecl()->getType()->isReferenceType()) // What the member refers to.
      merge(R, loadRoots(M->getBase(), Depth + 1));
    return R;
  }
  if (const auto *A = dyn_cast<ArraySubscriptExpr>(E))
    return pointeeRoots(A->getBase(), Depth + 1);
  if (const auto *U = dyn_cast<UnaryOperator>(E)) {
    if (U->getOpcode() == UO_Deref)
      return pointeeRoots(U->getSubExpr(), Depth + 1);
    if (U->isPrefix() && U->isIncrementDecrementOp())
      return objectRoots(U->getSubExpr(), Depth + 1);
    return {};
  }
  if (const auto *B = dyn_cast<BinaryOperator>(E)) {
    if (B->isAssignmentOp() || B->getOpcode() == BO_PtrMemD)
      return objectRoots(B->getLHS(), Depth + 1);
    if (B->getOpcode() == BO_PtrMemI)
      return pointeeRoots(B->getLHS(), Depth + 1);
    if (B->getOpcode() == BO_Comma)
      return objectRoots(B->getRHS(), Depth + 1);
    return {};
  }
  if (const auto *C = dyn_cast<AbstractConditionalOperator>(E)) {
    StorageRoots R = objectRoots(C->getTrueExpr(), Depth + 1);
    merge(R, objectRoots(C->getFalseExpr(), Depth + 1));
    return R;
  }
  if (isa<CallExpr>(E))
    return callRoots(E, Depth + 1);
  return {};
}

/// What the value of E (a pointer, an iterator, a class holding pointers)
/// may point into.
StorageRoots SharedStateFinder::pointeeRoots(const Expr *E, unsigned Depth) {
  E = strip(E);
  if (!E || Depth > MaxDepth)
    return {};
  QualType T = E->getType();
  if (T->isArithmeticType() || T->isEnumeralType() || T->isVoidType())
    return {}; // A number points nowhere.
  auto Key = std::make_pair(E, true);
  if (auto It = Cache.find(Key); It != Cache.end())
    return It->second;
  return Cache[Key] = pointeeRootsOf(E, Depth);
}

StorageRoots SharedStateFinder::pointeeRootsOf(const Expr *E, unsigned Depth) {
  // An aggregate or an initializer_list's array: what its elements hold.
  if (const auto *IL = dyn_cast<InitListExpr>(E)) {
    StorageRoots R;
    for (const Expr *Init : IL->inits()) {
      merge(R, pointeeRoots(Init, Depth + 1));
      if (Init->isGLValue()) // A reference member bound to it.
        merge(R, objectRoots(Init, Depth + 1));
    }
    return R;
  }
  if (E->getType()->isArrayType()) // Decayed to a pointer to its first element.
    return objectRoots(E, Depth + 1);
  if (const auto *U = dyn_cast<UnaryOperator>(E)) {
    if (U->getOpcode() == UO_AddrOf)
      return objectRoots(U->getSubExpr(), Depth + 1);
    if (U->isIncrementDecrementOp())
      return pointeeRoots(U->getSubExpr(), Depth + 1);
  }
  if (const auto *B = dyn_cast<BinaryOperator>(E)) {
    if (B->isAdditiveOp()) {
      StorageRoots R = pointeeRoots(B->getLHS(), Depth + 1);
      merge(R, pointeeRoots(B->getRHS(), Depth + 1));
      return R;
    }
    if (B->isAssignmentOp())
      return pointeeRoots(B->getLHS(), Depth + 1);
    if (B->getOpcode() == BO_Comma)
      return pointeeRoots(B->getRHS(), Depth + 1);
  }
  if (const auto *C = dyn_cast<AbstractConditionalOperator>(E)) {
    StorageRoots R = pointeeRoots(C->getTrueExpr(), Depth + 1);
    merge(R, pointeeRoots(C->getFalseExpr(), Depth + 1));
    return R;
  }
  if (isa<CallExpr>(E)) // A reference returned is read from; an iterator is what it points into.
    return E->isGLValue() ? loadRoots(E, Depth + 1) : callRoots(E, Depth + 1);
  if (const auto *CE = dyn_cast<CXXConstructExpr>(E)) {
    const CXXConstructorDecl *Ctor = CE->getConstructor();
    // A copy points where the original does, unless it copies deeply.
    if (Ctor->isCopyOrMoveConstructor() && CE->getNumArgs() >= 1)
      return Ctor->isUserProvided() ? StorageRoots{} : pointeeRoots(CE->getArg(0), Depth + 1);
    StorageRoots R;
    for (unsigned I = 0; I < CE->getNumArgs() && I < Ctor->getNumParams(); ++I)
      merge(R, argumentRoots(CE->getArg(I), Ctor->getParamDecl(I)->getType(), Depth + 1));
    return R;
  }
  if (E->isGLValue())
    return loadRoots(E, Depth + 1);
  return {};
}

/// What a pointer (or pointer-holding object) read from glvalue E points into.
StorageRoots SharedStateFinder::loadRoots(const Expr *E, unsigned Depth) {
  if (!holdsMutablePointer(E->getType()))
    return {};
  StorageRoots R;
  for (const StorageRoot &B : objectRoots(E, Depth + 1)) {
    if (B.Var->hasGlobalStorage() || isa<ParmVarDecl>(B.Var))
      R.insert({B.Var, true});
    if (!B.Var->hasGlobalStorage())
      merge(R, aliasesOf(B.Var));
  }
  return R;
}

/// A parameter of type Param bound to Arg reaches these.
StorageRoots SharedStateFinder::argumentRoots(const Expr *Arg, QualType Param, unsigned Depth) {
  StorageRoots R = pointeeRoots(Arg, Depth + 1);
  if (Param->isReferenceType())
    merge(R, objectRoots(Arg, Depth + 1));
  return R;
}

/// What a call's result (a reference, pointer or iterator) may point into:
/// for a helper, what its return statements do; for library code, anything
/// its object or arguments reach.
StorageRoots SharedStateFinder::callRoots(const Expr *Call, unsigned Depth) {
  const auto *CE = cast<CallExpr>(Call);
  const FunctionDecl *FD = CE->getDirectCallee();
  QualType Result = FD ? FD->getReturnType() : CE->getCallReturnType(Ctx);
  if (!Result->isReferenceType() && !Result->isPointerType() && !Result->isRecordType())
    return {};
  llvm::ArrayRef<const Expr *> Args = boundArguments(CE, FD);
  std::vector<QualType> Params = parameterTypes(CE, FD);
  StorageRoots R;
  if (followed(FD)) {
    const FunctionDecl *Def = FD->getDefinition();
    scanFunction(Def);
    for (const StorageRoot &Root : Returns[Def]) {
      const auto *P = dyn_cast<ParmVarDecl>(Root.Var);
      if (!P) {
        R.insert(Root);
        continue;
      }
      unsigned I = P->getFunctionScopeIndex();
      if (I < Args.size())
        merge(R, argumentRoots(Args[I], P->getType(), Depth + 1));
    }
  } else {
    for (unsigned I = 0; I < Args.size(); ++I)
      merge(R, I < Params.size() ? argumentRoots(Args[I], Params[I], Depth + 1)
                                 : pointeeRoots(Args[I], Depth + 1));
  }
  if (const Expr *Object = implicitObject(CE)) {
    // An iterator's or span's element is where it points; a container's
    // is in the container.
    const auto *OC = dyn_cast<CXXOperatorCallExpr>(CE);
    bool Access = OC && isOneOf(getOperatorSpelling(OC->getOperator()), {"*", "->", "[]"});
    if (!Access || !isShallow(FD))
      merge(R, objectRoots(Object, Depth + 1));
    if (!Access || isShallow(FD))
      merge(R, pointeeRoots(Object, Depth + 1));
  }
  return R;
}

/// What a local (or a parameter reassigned in its function) may point into.
const StorageRoots &SharedStateFinder::aliasesOf(const VarDecl *Local) {
  if (const auto *FD = dyn_cast_or_null<FunctionDecl>(Local->getParentFunctionOrMethod()))
    scanFunction(FD);
  return Aliases[Local];
}

/// Flow-insensitive: every initialiser and assignment anywhere in FD
/// (lambda bodies included) adds to what its target may point into, until
/// nothing changes; then what FD returns.
void SharedStateFinder::scanFunction(const FunctionDecl *FD) {
  const FunctionDecl *Def = FD->getDefinition();
  if (!Def || !Def->hasBody() || !Scanned.insert(Def).second)
    return;
  std::vector<std::pair<const VarDecl *, const Expr *>> Inits;
  std::vector<std::pair<const Expr *, const Expr *>> Assignments;
  std::vector<const Expr *> Returned;
  std::function<void(const Stmt *, bool)> Collect = [&](const Stmt *S, bool InLambda) {
    if (!S)
      return;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      for (const Expr *Init : L->capture_inits())
        Collect(Init, InLambda);
      Collect(L->getBody(), true);
      return;
    }
    if (const auto *DS = dyn_cast<DeclStmt>(S))
      for (const Decl *D : DS->decls())
        if (const auto *VD = dyn_cast<VarDecl>(D);
            VD && VD->getInit() && !VD->getType()->isReferenceType() && !VD->hasGlobalStorage())
          Inits.push_back({VD, VD->getInit()});
    if (const auto *B = dyn_cast<BinaryOperator>(S); B && B->getOpcode() == BO_Assign)
      Assignments.push_back({B->getLHS(), B->getRHS()});
    if (const auto *OC = dyn_cast<CXXOperatorCallExpr>(S);
        OC && OC->getOperator() == OO_Equal && OC->getNumArgs() == 2)
      Assignments.push_back({OC->getArg(0), OC->getArg(1)});
    if (const auto *RS = dyn_cast<ReturnStmt>(S); RS && RS->getRetValue() && !InLambda)
      Returned.push_back(RS->getRetValue());
    for (const Stmt *Child : S->children())
      Collect(Child, InLambda);
  };
  Collect(Def->getBody(), false);
  for (unsigned Round = 0; Round < 8; ++Round) {
    Cache.clear();
    bool Changed = false;
    auto Add = [&](const VarDecl *VD, const StorageRoots &R) {
      StorageRoots &Slot = Aliases[VD];
      size_t Before = Slot.size();
      merge(Slot, R);
      Changed |= Slot.size() != Before;
    };
    for (auto [VD, Init] : Inits)
      Add(VD, pointeeRoots(Init));
    for (auto [Target, Value] : Assignments) {
      StorageRoots R = pointeeRoots(Value);
      for (const StorageRoot &B : objectRoots(Target))
        if (!B.Var->hasGlobalStorage() && !B.Through)
          Add(B.Var, R);
    }
    if (!Changed)
      break;
  }
  Cache.clear();
  StorageRoots &Out = Returns[Def];
  bool ByReference = Def->getReturnType()->isReferenceType();
  for (const Expr *E : Returned) {
    StorageRoots R = pointeeRoots(E);
    if (ByReference)
      merge(R, objectRoots(E));
    for (const StorageRoot &Root : R)
      if (Root.Var->hasGlobalStorage() || (isa<ParmVarDecl>(Root.Var) && Root.Through))
        Out.insert(Root);
  }
}

/// Roots a statement writes: globals are reported, parameters remembered
/// for the calls that bind them.
void SharedStateFinder::written(const StorageRoots &Roots, const Stmt *At,
                                std::optional<std::string> Callee) {
  std::set<const VarDecl *> Reported;
  for (const StorageRoot &R : Roots) {
    if (const auto *P = dyn_cast<ParmVarDecl>(R.Var); P && R.Through) {
      WrittenParams.insert(P);
      continue;
    }
    if (!R.Var->hasGlobalStorage() || !isUserCode(Ctx.getSourceManager(), R.Var) ||
        !Reported.insert(R.Var).second)
      continue;
    std::string Name = R.Var->getQualifiedNameAsString();
    if (Callee)
      D.report(DiagId::GlobalPassedToWriter, At->getBeginLoc(),
               {KernelKind, Kernel, Name, *Callee});
    else
      D.report(DiagId::GlobalWriteInParticleKernel, At->getBeginLoc(), {KernelKind, Kernel, Name});
    D.report(DiagId::NoteSharedStateOptIn, At->getBeginLoc(), {Kernel});
  }
}

/// A lambda among Args writes through a parameter: the algorithm hands it
/// elements of what the other arguments point into.
bool SharedStateFinder::writesThroughCallable(llvm::ArrayRef<const Expr *> Args) const {
  for (const Expr *A : Args) {
    const CXXRecordDecl *RD = A->getType()->getAsCXXRecordDecl();
    if (!RD || !RD->isLambda())
      continue;
    std::vector<const FunctionDecl *> Operators{RD->getLambdaCallOperator()};
    if (const FunctionTemplateDecl *T = RD->getDependentLambdaCallOperator())
      for (const FunctionDecl *Spec : T->specializations())
        Operators.push_back(Spec);
    for (const FunctionDecl *Op : Operators)
      for (const ParmVarDecl *P : Op->parameters())
        if (WrittenParams.count(P))
          return true;
  }
  return false;
}

void SharedStateFinder::call(const Expr *Call, const FunctionDecl *FD,
                             llvm::ArrayRef<const Expr *> Args, llvm::ArrayRef<QualType> Params) {
  const FunctionDecl *Def = FD ? FD->getDefinition() : nullptr;
  if (followed(FD) || Walked.count(Def)) {
    for (unsigned I = 0; I < Args.size() && I < Def->getNumParams(); ++I)
      if (const ParmVarDecl *P = Def->getParamDecl(I); WrittenParams.count(P))
        written(argumentRoots(Args[I], P->getType(), 0), Args[I], nameOf(Def));
    return;
  }
  if (FD && changesHiddenState(FD)) {
    D.report(DiagId::SharedStateCallInParticleKernel, Call->getBeginLoc(),
             {KernelKind, Kernel, FD->getQualifiedNameAsString()});
    D.report(DiagId::NoteSharedStateOptIn, Call->getBeginLoc(), {Kernel});
    return;
  }
  if (FD && isLibraryAccessor(FD) && !writesThroughCallable(Args))
    return;
  for (unsigned I = 0; I < Args.size(); ++I) {
    bool Variadic = I >= Params.size();
    if (Variadic ? !holdsMutablePointer(Args[I]->getType()) : !mayWriteThrough(Params[I]))
      continue;
    StorageRoots R = Variadic ? pointeeRoots(Args[I]) : argumentRoots(Args[I], Params[I], 0);
    written(R, Args[I], nameOf(FD));
  }
}

void SharedStateFinder::writtenTarget(const Expr *Target, const Stmt *At) {
  if (const CXXRecordDecl *RD = heldThroughThis(Target))
    WritesThroughHeld.insert(RD->getCanonicalDecl());
  written(objectRoots(Target), At, std::nullopt);
}

/// What an object (or the object a pointer designates) holds pointers to.
StorageRoots SharedStateFinder::heldRoots(const Expr *Object) {
  const Expr *O = strip(Object);
  StorageRoots R;
  for (const StorageRoot &B : O->getType()->isPointerType() ? pointeeRoots(O) : objectRoots(O)) {
    if (B.Var->hasGlobalStorage() || (isa<ParmVarDecl>(B.Var) && B.Through))
      R.insert(B);
    else
      merge(R, aliasesOf(B.Var));
  }
  return R;
}

bool SharedStateFinder::writesThroughHeld(const CXXRecordDecl *RD) const {
  return RD && WritesThroughHeld.count(RD->getCanonicalDecl());
}

void SharedStateFinder::visit(const Stmt *S) {
  Cache.clear(); // Aliases may have grown since.
  if (const auto *B = dyn_cast<BinaryOperator>(S); B && B->isAssignmentOp())
    return writtenTarget(B->getLHS(), S);
  if (const auto *U = dyn_cast<UnaryOperator>(S); U && U->isIncrementDecrementOp())
    return writtenTarget(U->getSubExpr(), S);
  if (const auto *CE = dyn_cast<CXXConstructExpr>(S)) {
    const CXXConstructorDecl *Ctor = CE->getConstructor();
    walk(Ctor);
    std::vector<QualType> Params;
    for (const ParmVarDecl *P : Ctor->parameters())
      Params.push_back(P->getType());
    llvm::ArrayRef<const Expr *> Args(CE->getArgs(), CE->getNumArgs());
    if (!writesThroughHeld(Ctor->getParent()))
      return call(CE, Ctor, Args, Params);
    // Its members are bound to the arguments and written through.
    for (unsigned I = 0; I < Args.size() && I < Params.size(); ++I)
      if (mayWriteThrough(Params[I]))
        written(argumentRoots(Args[I], Params[I], 0), Args[I], nameOf(Ctor));
    return;
  }
  if (const auto *BT = dyn_cast<CXXBindTemporaryExpr>(S))
    return walk(BT->getTemporary()->getDestructor());
  if (const auto *DS = dyn_cast<DeclStmt>(S)) {
    for (const Decl *Dcl : DS->decls())
      if (const auto *VD = dyn_cast<VarDecl>(Dcl); VD && !VD->hasGlobalStorage())
        if (const CXXRecordDecl *RD = VD->getType()->getAsCXXRecordDecl();
            RD && RD->hasDefinition() && RD->getDestructor()) {
          walk(RD->getDestructor());
          if (writesThroughHeld(RD))
            written(aliasesOf(VD), DS, nameOf(RD->getDestructor()));
        }
    return;
  }
  const auto *CE = dyn_cast<CallExpr>(S);
  if (!CE)
    return;
  const FunctionDecl *FD = CE->getDirectCallee();
  // g(x), g += x on a class type, rng(), v.push_back(x): a non-const member
  // call on the object (library accessors only hand out access).
  if (const Expr *Object = implicitObject(CE)) {
    const auto *MD = dyn_cast_or_null<CXXMethodDecl>(FD);
    bool Accessor = MD && !followed(MD) && isLibraryAccessor(MD);
    if (MD && !MD->isConst() && !MD->isStatic() && !Accessor)
      writtenTarget(Object, S);
    if (MD && !MD->isStatic() && writesThroughHeld(MD->getParent()))
      written(heldRoots(Object), S, nameOf(MD));
  }
  std::vector<QualType> Params = parameterTypes(CE, FD);
  call(CE, FD, boundArguments(CE, FD), Params);
}

/// Constructors and destructors the kernel walk does not enter: walked
/// here, children first, into the user functions they call.
void SharedStateFinder::walk(const FunctionDecl *FD) {
  const FunctionDecl *Def = FD ? FD->getDefinition() : nullptr;
  if (!Def || !Def->hasBody() || !isUserCode(Ctx.getSourceManager(), Def) ||
      !Walked.insert(Def).second)
    return;
  std::function<void(const Stmt *)> Walk = [&](const Stmt *S) {
    if (!S)
      return;
    if (const auto *L = dyn_cast<LambdaExpr>(S)) {
      for (const Expr *Init : L->capture_inits())
        Walk(Init);
      return; // Walked where it is called.
    }
    for (const Stmt *Child : S->children())
      Walk(Child);
    if (const auto *CE = dyn_cast<CallExpr>(S); CE && followed(CE->getDirectCallee()))
      walk(CE->getDirectCallee());
    visit(S);
  };
  if (const auto *Ctor = dyn_cast<CXXConstructorDecl>(Def))
    for (const CXXCtorInitializer *Init : Ctor->inits())
      Walk(Init->getInit());
  Walk(Def->getBody());
}

bool allowsSharedState(const FunctionDecl *Kernel) {
  std::function<bool(const Stmt *)> Find = [&](const Stmt *S) {
    if (!S || isa<LambdaExpr>(S))
      return false;
    if (const auto *CE = dyn_cast<CallExpr>(S);
        CE && isWashCall(CE->getDirectCallee(), ApiCall::allow_shared_state))
      return true;
    for (const Stmt *Child : S->children())
      if (Find(Child))
        return true;
    return false;
  };
  return Find(Kernel->getBody());
}

} // namespace wash::tr
