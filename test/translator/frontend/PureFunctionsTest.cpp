//===- PureFunctionsTest.cpp - what may move out of the pair loop ---------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/PureFunctions.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

TEST(PureFunctions, AValueOfItsArgumentsAndConstantsOnly) {
  withAst(R"(#include <wash/wash.hpp>
#include <cmath>
const double Gamma = 1.4;
double Counter = 0;
double eos(double rho) { return std::pow(rho, Gamma) / Gamma; }
double viaHelper(double rho) { double x = eos(rho); return x * 2; }
double readsMutable(double rho) { return rho * Counter; }
double writesGlobal(double rho) { Counter = rho; return rho; }
double loops(double rho) { for (int i = 0; i < 3; ++i) rho *= 2; return rho; }
int integerDivision(int a) { return 10 / a; }
int main() {}
)",
          [](ASTContext &Ctx, Diagnoser &) {
            Purity Pure(Ctx.getSourceManager());
            EXPECT_TRUE(Pure.pure(function(Ctx, "eos")));
            EXPECT_TRUE(Pure.pure(function(Ctx, "viaHelper")));
            EXPECT_FALSE(Pure.pure(function(Ctx, "readsMutable")));
            EXPECT_FALSE(Pure.pure(function(Ctx, "writesGlobal")));
            EXPECT_FALSE(Pure.pure(function(Ctx, "loops")));
            EXPECT_FALSE(Pure.pure(function(Ctx, "integerDivision"))); // undefined for a = 0
          });
}

} // namespace
