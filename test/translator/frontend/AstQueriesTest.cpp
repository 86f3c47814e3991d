//===- AstQueriesTest.cpp - one peel, one only-read ------------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/AstQueries.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/ExprCXX.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

const VarDecl *local(const FunctionDecl *FD, const std::string &Name) {
  for (const Decl *D : FD->decls())
    if (const auto *V = dyn_cast<VarDecl>(D); V && V->getNameAsString() == Name)
      return V;
  return nullptr;
}

TEST(AstQueries, PeelLooksThroughCopiesAndConversionsOnly) {
  withAst(R"(#include <wash/wash.hpp>
#include <string>
void take(std::string s) {}
void take_int(int i) {}
int main() { take(std::string("x")); take_int((int)2.5); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            const Expr *S = argument(Ctx, "take", 0, 0);
            // By default a functional cast stays: it is not a copy.
            EXPECT_FALSE(isa<StringLiteral>(peel(S)));
            PeelOptions Strings;
            Strings.FunctionalCasts = true;
            // std::string(const char *, const Alloc & = Alloc()).
            Strings.IsCopy = [](const CXXConstructExpr *CE) {
              return CE->getNumArgs() == 2 && isa<CXXDefaultArgExpr>(CE->getArg(1));
            };
            EXPECT_TRUE(isa<StringLiteral>(peel(S, Strings)));
            const Expr *I = argument(Ctx, "take_int", 0, 0);
            EXPECT_TRUE(isa<CStyleCastExpr>(peel(I)));
            PeelOptions Casts;
            Casts.ExplicitCasts = true;
            EXPECT_TRUE(isa<FloatingLiteral>(peel(I, Casts)));
          });
}

TEST(AstQueries, PeelFollowsVariablesOnlyWhenAsked) {
  withAst(R"(#include <wash/wash.hpp>
template <class F> void call(F f) { f(); }
int main() { auto l = [] {}; auto copy = l; call(copy); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            const Expr *A = argument(Ctx, "call", 0, 0);
            EXPECT_FALSE(isa<LambdaExpr>(peel(A)));
            PeelOptions Vars;
            Vars.VariableInitialisers = true;
            Vars.IsCopy = constructsFromOneArgument;
            EXPECT_TRUE(isa<LambdaExpr>(peel(A, Vars)));
          });
}

TEST(AstQueries, PeelStopsAtAVariableInitialisedWithItself) {
  withAst(R"(#include <wash/wash.hpp>
void take(int i) {}
int main() { int x = x; take(x); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            PeelOptions Vars;
            Vars.VariableInitialisers = true;
            EXPECT_NE(peel(argument(Ctx, "take", 0, 0), Vars), nullptr);
          });
}

TEST(AstQueries, OnlyReadSeesEveryWayAVariableMayChange) {
  withAst(R"(#include <wash/wash.hpp>
void by_value(double) {}
void by_const(const double &) {}
void by_ref(double &) {}
void f() {
  double read = 1, passed = 2, bound = 3, assigned = 4, incremented = 5, addressed = 6,
         in_lambda = 7, referenced = 8;
  double x = read + (read);
  by_value(passed);
  by_const(passed);
  by_ref(bound);
  assigned = 1;
  ++incremented;
  double *p = &addressed;
  auto l = [&] { in_lambda = 2; };
  double &r = referenced;
}
int main() {}
)",
          [](ASTContext &Ctx, Diagnoser &) {
            const FunctionDecl *F = function(Ctx, "f");
            ASSERT_NE(F, nullptr);
            EXPECT_TRUE(onlyRead(local(F, "read"), F->getBody()));
            EXPECT_TRUE(onlyRead(local(F, "passed"), F->getBody()));
            for (const char *Changed :
                 {"bound", "assigned", "incremented", "addressed", "in_lambda", "referenced"})
              EXPECT_FALSE(onlyRead(local(F, Changed), F->getBody())) << Changed;
          });
}

} // namespace
