//===- CollectSimulationTest.cpp - what main registers, in C++'s order ----===//
#include "AstSnippet.h"

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/CollectSimulation.h"

#include <gtest/gtest.h>

using namespace clang;
using namespace wash::tr;
using namespace wash::tr::test;

namespace {

std::vector<std::string> forcesOf(const std::string &Code, bool &Ok) {
  std::vector<std::string> Names;
  withAst(Code, [&](ASTContext &Ctx, Diagnoser &D) {
    AstRefs Refs;
    ProgramIndex Index(Ctx);
    std::optional<Registrations> R = collectSimulation(Index, D, 2, Refs);
    Ok = R.has_value();
    if (R)
      for (const ForceRegistration &F : R->Forces)
        Names.push_back(F.Name);
  });
  return Names;
}

TEST(CollectSimulation, AHelperRegistersWhatEachCallPasses) {
  bool Ok = false;
  auto Names = forcesOf(R"(#include <wash/wash.hpp>
void add(const std::string &n, int d = 1) { wash::add_force(n, d); }
void pair(const char *a, const char *b) { add(a); add(b, 2); }
int main() { wash::set_influence_radius(1); pair("x", "v"); add("y"); wash::start(); }
)",
                        Ok);
  EXPECT_TRUE(Ok);
  EXPECT_EQ(Names, (std::vector<std::string>{"x", "v", "y"}));
}

TEST(CollectSimulation, ArgumentsRegisterBeforeTheCallTheyArePassedTo) {
  bool Ok = false;
  auto Names = forcesOf(R"(#include <wash/wash.hpp>
int reg(const char *n) { wash::add_force(n, 1); return 0; }
void after(int) { wash::add_force("second", 1); }
int main() { wash::set_influence_radius(1); after(reg("first")); wash::start(); }
)",
                        Ok);
  EXPECT_TRUE(Ok);
  EXPECT_EQ(Names, (std::vector<std::string>{"first", "second"}));
}

TEST(CollectSimulation, UnsequencedRegistrationsAreRejected) {
  bool Ok = true;
  forcesOf(R"(#include <wash/wash.hpp>
int reg(const char *n) { wash::add_force(n, 1); return 0; }
int both(int, int) { return 0; }
int main() { wash::set_influence_radius(1); both(reg("a"), reg("b")); wash::start(); }
)",
           Ok);
  EXPECT_FALSE(Ok);
}

} // namespace
