//===- ParameterBindingsTest.cpp ------------------------------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/ParameterBindings.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

const ParmVarDecl *param(ASTContext &Ctx, const std::string &Function, unsigned I) {
  const FunctionDecl *FD = function(Ctx, Function);
  return FD && I < FD->getNumParams() ? FD->getParamDecl(I) : nullptr;
}

TEST(ParameterBindings, AnArgumentIsMatchedToItsParameterNotToTheObject) {
  withAst(R"(#include <wash/wash.hpp>
struct Namer { const char *operator()(int k, const char *n) const { return n; } };
const char *pick(int k, const char *n = "d") { return n; }
int main() { Namer f; f(1, "x"); pick(2, "y"); pick(3); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            const CallExpr *Op = calls(Ctx, "operator()").at(0);
            const FunctionDecl *Callee = Op->getDirectCallee();
            const Expr *N = argumentFor(Op, Callee, Callee->getParamDecl(1));
            ASSERT_NE(N, nullptr);
            EXPECT_TRUE(isa<StringLiteral>(N->IgnoreImpCasts()));
            const CallExpr *Defaulted = calls(Ctx, "pick").at(1);
            EXPECT_TRUE(isa<CXXDefaultArgExpr>(
                argumentFor(Defaulted, Defaulted->getDirectCallee(), param(Ctx, "pick", 1))));
            // Another function's parameter is not bound by this call.
            EXPECT_EQ(argumentFor(Defaulted, Defaulted->getDirectCallee(),
                                  Callee->getParamDecl(1)),
                      nullptr);
          });
}

TEST(ParameterBindings, EveryCallOfADirectlyCalledFunctionIsVisible) {
  withAst(R"(#include <wash/wash.hpp>
void name(const char *n) {}
template <class T> void twice(T t) { name("b"); }
int main() { name("a"); twice(1); twice(2.0); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            // main's, and the call in the template's body and in each of its
            // two instantiations.
            EXPECT_EQ(visibleCalls(param(Ctx, "name", 0), Ctx).size(), 4u);
          });
}

TEST(ParameterBindings, NoCallsAreKnownOfAFunctionWhoseAddressIsTaken) {
  withAst(R"(#include <wash/wash.hpp>
#include <functional>
void name(const char *n) {}
void other(const char *n) {}
auto lambda = [](const char *n) {};
int main() { name("a"); std::function<void(const char *)> f = &name; f("z");
             other("b"); lambda("c"); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            EXPECT_TRUE(visibleCalls(param(Ctx, "name", 0), Ctx).empty());
            EXPECT_EQ(visibleCalls(param(Ctx, "other", 0), Ctx).size(), 1u);
            // A lambda's calls can hide in library code it is passed to.
            const CallExpr *L = calls(Ctx, "operator()").at(0);
            EXPECT_TRUE(visibleCalls(L->getDirectCallee()->getParamDecl(0), Ctx).empty());
          });
}

} // namespace
