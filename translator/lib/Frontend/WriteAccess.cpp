//===- WriteAccess.cpp ----------------------------------------------------===//
#include "wash/translator/Frontend/WriteAccess.h"
#include "wash/translator/Frontend/WashApi.h"

#include "clang/AST/DeclCXX.h"

using namespace clang;

namespace wash::tr {

bool holdsMutablePointer(QualType T, unsigned Depth) {
  if (Depth > 4 || T.isNull())
    return false;
  if (T->isPointerType() || T->isReferenceType())
    return !T->getPointeeType().isConstQualified();
  if (const auto *A = T->getAsArrayTypeUnsafe())
    return holdsMutablePointer(A->getElementType(), Depth + 1);
  const auto *RD = T->getAsCXXRecordDecl();
  if (!RD || !RD->hasDefinition())
    return false;
  for (const FieldDecl *F : RD->fields())
    if (holdsMutablePointer(F->getType(), Depth + 1))
      return true;
  for (const CXXBaseSpecifier &B : RD->bases())
    if (holdsMutablePointer(B.getType(), Depth + 1))
      return true;
  return false;
}

bool shallowWhenConst(QualType T, unsigned Depth) {
  if (T->isPointerType() || T->isReferenceType())
    return !T->getPointeeType().isConstQualified();
  const auto *RD = T->getAsCXXRecordDecl();
  if (!RD || !RD->hasDefinition() || Depth > 4)
    return false;
  for (const FieldDecl *F : RD->fields())
    if (F->getAccess() == AS_public && shallowWhenConst(F->getType(), Depth + 1))
      return true;
  for (const CXXMethodDecl *M : RD->methods()) {
    QualType R = M->getReturnType();
    OverloadedOperatorKind O = M->getOverloadedOperator();
    bool Access = O == OO_Star || O == OO_Arrow || O == OO_Subscript ||
                  (M->getIdentifier() && M->getName() == "get");
    if (Access && M->isConst() && (R->isReferenceType() || R->isPointerType()) &&
        !R->getPointeeType().isConstQualified())
      return true;
  }
  for (const CXXBaseSpecifier &B : RD->bases())
    if (B.getAccessSpecifier() == AS_public && shallowWhenConst(B.getType(), Depth + 1))
      return true;
  return false;
}

bool mayWriteThrough(QualType T) {
  if (const auto *R = T->getAs<ReferenceType>())
    return !R->getPointeeType().isConstQualified() || shallowWhenConst(R->getPointeeType());
  return holdsMutablePointer(T);
}

bool isLibraryAccessor(const FunctionDecl *FD) {
  switch (FD->getOverloadedOperator()) {
  case OO_None:
    break;
  case OO_Subscript:
  case OO_Star:
  case OO_Arrow: // Access.
  case OO_EqualEqual:
  case OO_ExclaimEqual:
  case OO_Less:
  case OO_Greater:
  case OO_LessEqual:
  case OO_GreaterEqual:
  case OO_Spaceship: // Comparison.
  case OO_Plus:
  case OO_Minus:
  case OO_Slash:
  case OO_Percent:
  case OO_Exclaim:
  case OO_Tilde:
  case OO_AmpAmp:
  case OO_PipePipe: // Arithmetic: a new value.
    return true;
  default:
    return false;
  }
  if (!FD->getIdentifier())
    return isa<CXXConversionDecl>(FD);
  if (isOneOf(FD->getName(),
              {"begin",       "end",         "cbegin", "cend",  "rbegin",    "rend",
               "crbegin",     "crend",       "data",   "size",  "empty",     "front",
               "back",        "at",          "find",   "count", "contains",  "lower_bound",
               "upper_bound", "equal_range", "get",    "value", "addressof", "ref",
               "cref",        "as_const",    "next",   "prev",  "distance",  "base"}))
    return true;
  return FD->isInStdNamespace() &&
         isOneOf(FD->getName(),
                 {"accumulate",     "reduce",    "inner_product", "transform_reduce",
                  "count_if",       "find_if",   "find_if_not",   "all_of",
                  "any_of",         "none_of",   "max_element",   "min_element",
                  "minmax_element", "equal",     "mismatch",      "lexicographical_compare",
                  "binary_search",  "is_sorted", "search",        "adjacent_find",
                  "includes"});
}

bool changesHiddenState(const FunctionDecl *FD) {
  if (const auto *MD = dyn_cast<CXXMethodDecl>(FD))
    return MD->getOverloadedOperator() == OO_Call && MD->getParent()->getIdentifier() &&
           MD->getParent()->getName() == "random_device" && MD->getParent()->isInStdNamespace();
  if (!FD->getIdentifier() || !(FD->isExternC() || FD->isInStdNamespace() ||
                                FD->getDeclContext()->getRedeclContext()->isTranslationUnit()))
    return false;
  return isOneOf(FD->getName(),
                 {"rand", "srand", "random", "srandom", "drand48", "lrand48", "mrand48", "srand48",
                  "seed48", "lcong48", "random_shuffle", "strtok"});
}

bool isShallow(const FunctionDecl *FD) {
  const auto *MD = dyn_cast_or_null<CXXMethodDecl>(FD);
  if (!MD)
    return true;
  QualType R = MD->getReturnType();
  return MD->isConst() && (R->isReferenceType() || R->isPointerType()) &&
         !R->getPointeeType().isConstQualified();
}

} // namespace wash::tr
