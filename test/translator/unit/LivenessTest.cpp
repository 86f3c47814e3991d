#include "wash/translator/Analysis/Liveness.h"
#include "TestModels.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Analysis/SummariseAccesses.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

static Model analysed(Model M) {
  summariseAccesses(M);
  resolveFields(M);
  computeLiveness(M);
  return M;
}

TEST(Liveness, UntouchedRegisteredForceIsDeadAndWarned) {
  Model M;
  M.Forces.push_back({"unused", ForceKind::Vector, {"sim.cpp", 7, 3}});
  M = analysed(M);
  EXPECT_FALSE(M.findField("unused")->Live);
  ASSERT_EQ(M.Findings.size(), 1u);
  EXPECT_EQ(M.Findings[0].Id, DiagId::ForceUnused);
  EXPECT_EQ(M.Findings[0].Pos.Line, 7u);
}

TEST(Liveness, WrittenOnlyIsLiveOutputOnlyAndReadIsNot) {
  Model M;
  M.Forces.push_back({"w", ForceKind::Scalar, {}});
  M.Forces.push_back({"r", ForceKind::Scalar, {}});
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {force("w", ForceKind::Scalar, Mode::Write, 1), neighbour("r")}));
  M = analysed(M);
  EXPECT_TRUE(M.findField("w")->Live);
  EXPECT_TRUE(M.findField("w")->OutputOnly);
  EXPECT_TRUE(M.findField("r")->Live);
  EXPECT_FALSE(M.findField("r")->OutputOnly);
  EXPECT_TRUE(M.Findings.empty());
}

TEST(Liveness, OutputColumnsAlwaysLiveButAccIsNot) {
  Model M = analysed(Model{});
  for (const char *F : {"id", "pos", "vel", "density", "mass", "smoothing_length"})
    EXPECT_TRUE(M.findField(F)->Live) << F;
  EXPECT_FALSE(M.findField("acc")->Live);
}
