//===- WashApiTest.cpp - evaluating names as C++ does ---------------------===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/ParameterBindings.h"
#include "wash/translator/Frontend/WashApi.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

std::optional<std::string> nameAt(ASTContext &Ctx, const std::string &Callee, unsigned N,
                                  const CallContext *Context = nullptr) {
  return evaluateString(argument(Ctx, Callee, N, 0), Ctx, Context);
}

TEST(WashApi, StringsEvaluateAsCxxReadsThem) {
  withAst(R"(#include <wash/wash.hpp>
#include <string>
constexpr const char *kHeat = "heat";
const std::string kCold = "cold";
void use(const std::string &) {}
int main() { use("a\0b"); use(kHeat); use(kCold); use(&"xyz"[1]); std::string v = "v"; use(v); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            EXPECT_EQ(nameAt(Ctx, "use", 0), "a");
            EXPECT_EQ(nameAt(Ctx, "use", 1), "heat");
            EXPECT_EQ(nameAt(Ctx, "use", 2), "cold");
            EXPECT_EQ(nameAt(Ctx, "use", 3), "yz");
            EXPECT_EQ(nameAt(Ctx, "use", 4), std::nullopt); // not const
          });
}

TEST(WashApi, AParameterIsWhatItsCallsBindNotItsDefault) {
  withAst(R"(#include <wash/wash.hpp>
void use(const char *) {}
void one(const char *const n = "alpha") { use(n); }
void two(const char *const n = "alpha") { use(n); }
void changed(const char *n) { n = "z"; use(n); }
int main() { one("beta"); one("beta"); two("beta"); two(); changed("c"); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            EXPECT_EQ(nameAt(Ctx, "use", 0), "beta");      // every call agrees
            EXPECT_EQ(nameAt(Ctx, "use", 1), std::nullopt); // "beta" and the default
            EXPECT_EQ(nameAt(Ctx, "use", 2), std::nullopt); // the body changes it
          });
}

TEST(WashApi, ACallContextBindsEachParameterExactly) {
  withAst(R"(#include <wash/wash.hpp>
void use(const char *, int) {}
void inner(const char *const n, int d = 3) { use(n, d); }
void outer(const char *const m) { inner(m); }
int main() { outer("first"); outer("second"); }
)",
          [](ASTContext &Ctx, Diagnoser &) {
            const CallExpr *Outer = calls(Ctx, "outer").at(1);
            const CallExpr *Inner = calls(Ctx, "inner").at(0);
            CallContext First{Outer, Outer->getDirectCallee(), nullptr};
            CallContext Second{Inner, Inner->getDirectCallee(), &First};
            EXPECT_EQ(nameAt(Ctx, "use", 0, &Second), "second");
            EXPECT_EQ(evaluateInt(argument(Ctx, "use", 0, 1), Ctx, &Second), 3);
            // Without the context the two calls of outer disagree.
            EXPECT_EQ(nameAt(Ctx, "use", 0), std::nullopt);
          });
}

} // namespace
