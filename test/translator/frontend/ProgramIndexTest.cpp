//===- ProgramIndexTest.cpp - the call graph, and walks with one budget ---===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/ProgramIndex.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

TEST(ProgramIndex, CallsFromLambdasAndAddressesMayRunAnywhere) {
  withAst(R"(#include <wash/wash.hpp>
void leaf() {}
void helper() { leaf(); }
void from_lambda() {}
void addressed() {}
void kernel(wash::Particle &p) { helper(); }
int main() {
  auto l = [] { from_lambda(); };
  void (*f)() = addressed;
  wash::add_update_kernel(kernel);
}
)",
          [](ASTContext &Ctx, Diagnoser &) {
            ProgramIndex Index(Ctx);
            EXPECT_EQ(Index.main(), function(Ctx, "main"));
            const auto &Anywhere = Index.runAnywhere();
            EXPECT_TRUE(Anywhere.count(function(Ctx, "from_lambda")->getCanonicalDecl()));
            EXPECT_TRUE(Anywhere.count(function(Ctx, "addressed")->getCanonicalDecl()));
            // Registering a kernel names it, but does not let it run anywhere.
            EXPECT_FALSE(Anywhere.count(function(Ctx, "kernel")->getCanonicalDecl()));
            auto Reached = Index.reachableFrom({function(Ctx, "kernel")});
            EXPECT_EQ(Reached.size(), 3u); // kernel, helper, leaf
            EXPECT_TRUE(Reached.count(function(Ctx, "leaf")->getCanonicalDecl()));
            EXPECT_EQ(Index.callsOf(function(Ctx, "leaf")).size(), 1u);
          });
}

TEST(ProgramIndex, AWalkFindsRecursion) {
  withAst(R"(#include <wash/wash.hpp>
void f() {}
int main() {}
)",
          [](ASTContext &Ctx, Diagnoser &) {
            ProgramIndex Index(Ctx);
            CallWalk<int> Walk(Index);
            const FunctionDecl *F = function(Ctx, "f");
            EXPECT_EQ(Walk.push(F, 7), CallWalk<int>::Entry::Entered);
            EXPECT_EQ(Walk.push(F, 8), CallWalk<int>::Entry::Recursive);
            ASSERT_NE(Walk.find(F), nullptr);
            EXPECT_EQ(*Walk.find(F), 7);
            Walk.pop();
            EXPECT_EQ(Walk.find(F), nullptr);
          });
}

TEST(ProgramIndex, AllWalksShareOneBudget) {
  withAst(R"(#include <wash/wash.hpp>
void f() {}
void g() {}
int main() {}
)",
          [](ASTContext &Ctx, Diagnoser &) {
            ProgramIndex Index(Ctx, /*Budget=*/3);
            CallWalk<> First(Index), Second(Index);
            const FunctionDecl *F = function(Ctx, "f"), *G = function(Ctx, "g");
            EXPECT_EQ(First.enter(F, [] {}), CallWalk<>::Entry::Entered);
            EXPECT_EQ(First.enter(G, [] {}), CallWalk<>::Entry::Entered);
            EXPECT_EQ(Second.enter(F, [] {}), CallWalk<>::Entry::Entered);
            bool Ran = false;
            EXPECT_EQ(Second.enter(G, [&] { Ran = true; }), CallWalk<>::Entry::OverBudget);
            EXPECT_FALSE(Ran);
            EXPECT_TRUE(Index.spent());
            EXPECT_TRUE(Index.firstOverrun());
            EXPECT_FALSE(Index.firstOverrun());
          });
}

} // namespace
