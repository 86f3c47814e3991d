#include "wash/translator/Analysis/ForceUses.h"
#include "TestModels.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Names.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

std::vector<Finding> check(Model M) {
  summarise(M);
  M.Fields = resolveFields(M.Sim.Dimension, M.Forces, M.Kernels).Fields;
  return checkForceUses(M.Fields, M.Kernels);
}

} // namespace

TEST(ClosestName, OffersOnlyCloseOtherNames) {
  EXPECT_EQ(closestName("presure", {"position", "pressure"}), "pressure");
  EXPECT_EQ(closestName("dT", {"dt", "T"}), "dt"); // ties: the first
  EXPECT_EQ(closestName("heat", {"heat", "pressure"}), std::nullopt);
  EXPECT_EQ(closestName("abc", {"xyz"}), std::nullopt);
}

TEST(ForceUses, ReadNeverWrittenIsAnErrorWithASuggestion) {
  Model M;
  M.Forces.push_back({"pressure", ForceKind::Scalar, {"sim.cpp", 9, 19}});
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {force("presure", ForceKind::Scalar, Mode::Read, 4),
                              force("pressure", ForceKind::Scalar, Mode::Write, 5)}));
  std::vector<Finding> F = check(M);
  ASSERT_EQ(F.size(), 1u);
  EXPECT_EQ(F[0].Id, DiagId::ForceNeverWrittenSuggest);
  EXPECT_EQ(F[0].Pos.Line, 4u);
  EXPECT_EQ(F[0].Args, (std::vector<std::string>{"presure", "pressure"}));
  ASSERT_EQ(F[0].Notes.size(), 1u);
  EXPECT_EQ(F[0].Notes[0].Pos.Line, 9u);
}

TEST(ForceUses, RegisteredReadNeverWrittenIsAnErrorToo) {
  Model M;
  M.Forces.push_back({"heat", ForceKind::Scalar, {}});
  M.Kernels.push_back(
      kernel(KernelKind::Update, "k", {force("heat", ForceKind::Scalar, Mode::Read, 3)}));
  std::vector<Finding> F = check(M);
  ASSERT_EQ(F.size(), 1u);
  EXPECT_EQ(F[0].Id, DiagId::ForceNeverWritten);
}

TEST(ForceUses, WrittenOnlyWarnsOnlyNearAReadForce) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Update, "k",
                             {force("temperature", ForceKind::Scalar, Mode::Read, 2),
                              force("temperature", ForceKind::Scalar, Mode::Write, 2),
                              force("viscosity", ForceKind::Scalar, Mode::Write, 3),
                              force("temprature", ForceKind::Scalar, Mode::Write, 4)}));
  std::vector<Finding> F = check(M);
  ASSERT_EQ(F.size(), 1u);
  EXPECT_EQ(F[0].Id, DiagId::ForceNeverRead);
  EXPECT_EQ(F[0].Pos.Line, 4u);
}

TEST(ForceNameProblem, IdentifiersThatAreNotBuiltins) {
  EXPECT_EQ(forceNameProblem("nearDensity"), std::nullopt);
  EXPECT_EQ(forceNameProblem("_h2"), std::nullopt);
  EXPECT_EQ(forceNameProblem(""), "is empty");
  EXPECT_EQ(forceNameProblem("a b"), "is not an identifier");
  EXPECT_EQ(forceNameProblem("2x"), "is not an identifier");
  EXPECT_EQ(forceNameProblem(std::string("a\0b", 3)), "is not an identifier");
  for (const char *B : {"id", "pos", "vel", "acc", "density", "mass", "smoothing_length"})
    EXPECT_EQ(forceNameProblem(B), "is a builtin particle property") << B;
}
