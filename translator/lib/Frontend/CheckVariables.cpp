//===- CheckVariables.cpp -------------------------------------------------===//
#include "wash/translator/Frontend/CheckVariables.h"
#include "wash/translator/Frontend/WashApi.h"
#include "wash/translator/Names.h"

#include "clang/AST/RecursiveASTVisitor.h"

#include <algorithm>

using namespace clang;

namespace wash::tr {
namespace {

struct Use {
  std::string Name;
  SourceLocation Loc;
};

class VariableCalls : public RecursiveASTVisitor<VariableCalls> {
public:
  VariableCalls(ASTContext &Ctx) : Ctx(Ctx) {}

  bool TraverseDecl(Decl *Dcl) {
    if (Dcl && !isa<TranslationUnitDecl>(Dcl) && !isUserCode(Ctx.getSourceManager(), Dcl))
      return true;
    return RecursiveASTVisitor::TraverseDecl(Dcl);
  }

  bool VisitCallExpr(CallExpr *CE) {
    const ApiCallInfo *Call = washCall(CE->getDirectCallee());
    if (!Call)
      return true;
    unsigned NameArg = Call->Id == ApiCall::add_reduction_kernel ? 2 : 0;
    bool Adds = Call->Id == ApiCall::add_variable;
    if (!Adds && Call->Id != ApiCall::get_variable && Call->Id != ApiCall::set_variable &&
        Call->Id != ApiCall::add_reduction_kernel)
      return true;
    if (CE->getNumArgs() <= NameArg)
      return true;
    const Expr *Arg = CE->getArg(NameArg);
    std::optional<std::string> Name = evaluateString(Arg, Ctx);
    if (Adds && !Name)
      AnyName = true;
    else if (Adds)
      Added.push_back(*Name);
    else if (Name && !(Call->Id == ApiCall::add_reduction_kernel && *Name == TimeStepTarget))
      Uses.push_back({*Name, Arg->getExprLoc()}); // "time_step" is the time step, not a variable
    return true;
  }

  std::vector<std::string> Added;
  std::vector<Use> Uses;
  bool AnyName = false; ///< An add_variable whose name is known only at run time.

private:
  ASTContext &Ctx;
};

} // namespace

bool checkVariables(ASTContext &Ctx, Diagnoser &D) {
  VariableCalls V(Ctx);
  V.TraverseAST(Ctx);
  if (V.AnyName)
    return true;
  bool Ok = true;
  for (const Use &U : V.Uses) {
    if (std::find(V.Added.begin(), V.Added.end(), U.Name) != V.Added.end())
      continue;
    Ok = false;
    if (std::optional<std::string> Close = closestName(U.Name, V.Added))
      D.report(DiagId::VariableUnknownSuggest, U.Loc, {escapedName(U.Name), *Close});
    else
      D.report(DiagId::VariableUnknown, U.Loc, {escapedName(U.Name)});
  }
  return Ok;
}

} // namespace wash::tr
