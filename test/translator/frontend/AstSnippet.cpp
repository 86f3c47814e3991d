//===- AstSnippet.cpp -----------------------------------------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/Parse.h"

#include "clang/AST/RecursiveASTVisitor.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/raw_ostream.h"

#include <gtest/gtest.h>

using namespace clang;

namespace wash::tr::test {
namespace {

class Finder : public RecursiveASTVisitor<Finder> {
public:
  Finder(std::string Name, const SourceManager &SM) : Name(std::move(Name)), SM(SM) {}
  bool shouldVisitTemplateInstantiations() const { return true; }
  bool shouldVisitLambdaBody() const { return true; }

  bool VisitFunctionDecl(FunctionDecl *FD) {
    if (!Function && FD->isThisDeclarationADefinition() && FD->getNameAsString() == Name &&
        SM.isInMainFile(SM.getExpansionLoc(FD->getLocation())))
      Function = FD;
    return true;
  }
  bool VisitCallExpr(CallExpr *CE) {
    const FunctionDecl *FD = CE->getDirectCallee();
    if (FD && FD->getNameAsString() == Name &&
        SM.isInMainFile(SM.getExpansionLoc(CE->getBeginLoc())))
      Calls.push_back(CE);
    return true;
  }

  std::string Name;
  const SourceManager &SM;
  const FunctionDecl *Function = nullptr;
  std::vector<const CallExpr *> Calls;
};

} // namespace

bool withAst(const std::string &Code,
             const std::function<void(ASTContext &, Diagnoser &)> &Body) {
  llvm::SmallString<128> Path;
  if (llvm::sys::fs::createTemporaryFile("snippet", "cpp", Path)) {
    ADD_FAILURE() << "cannot create a temporary file";
    return false;
  }
  {
    std::error_code EC;
    llvm::raw_fd_ostream Out(Path, EC);
    Out << Code;
  }
  Options Opts;
  Opts.Source = std::string(Path);
  bool Ran = false;
  bool Parsed = parseSimulation(
      Opts, [&](ASTContext &Ctx, Diagnoser &D, unsigned, const IncludeDirectives &) {
        Ran = true;
        Body(Ctx, D);
      });
  llvm::sys::fs::remove(Path);
  EXPECT_TRUE(Ran) << "clang rejected the snippet";
  return Parsed && Ran;
}

const FunctionDecl *function(ASTContext &Ctx, const std::string &Name) {
  Finder F(Name, Ctx.getSourceManager());
  F.TraverseAST(Ctx);
  return F.Function;
}

std::vector<const CallExpr *> calls(ASTContext &Ctx, const std::string &Callee) {
  Finder F(Callee, Ctx.getSourceManager());
  F.TraverseAST(Ctx);
  return F.Calls;
}

const Expr *argument(ASTContext &Ctx, const std::string &Callee, unsigned N, unsigned I) {
  std::vector<const CallExpr *> Found = calls(Ctx, Callee);
  if (N >= Found.size() || I >= Found[N]->getNumArgs())
    return nullptr;
  return Found[N]->getArg(I);
}

} // namespace wash::tr::test
