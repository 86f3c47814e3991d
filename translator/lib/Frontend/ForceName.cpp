//===- ForceName.cpp ------------------------------------------------------===//
#include "wash/translator/Frontend/ForceName.h"
#include "wash/translator/Frontend/WashApi.h"
#include "wash/translator/Names.h"

#include "clang/Basic/IdentifierTable.h"

using namespace clang;

namespace wash::tr {

std::optional<std::string> forceName(const Expr *NameArg, ASTContext &Ctx, Diagnoser &D,
                                     const CallContext *Context) {
  std::optional<std::string> Name = evaluateString(NameArg, Ctx, Context);
  if (!Name) {
    D.report(DiagId::ForceNameNotConstant, NameArg->getExprLoc());
    return std::nullopt;
  }
  std::optional<std::string> Problem = forceNameProblem(*Name);
  if (!Problem) {
    // The compiler's own tables: the generated code is compiled as C++20
    // with the program's macros.
    const IdentifierInfo &II = Ctx.Idents.get(*Name);
    if (II.isKeyword(Ctx.getLangOpts()) || II.isCPlusPlusOperatorKeyword())
      Problem = "is a C++ keyword";
    else if (II.hasMacroDefinition())
      Problem = "is a macro";
  }
  if (Problem) {
    D.report(DiagId::ForceNameInvalid, NameArg->getExprLoc(), {escapedName(*Name), *Problem});
    return std::nullopt;
  }
  return Name;
}

} // namespace wash::tr
