#include "wash/translator/Analysis/Liveness.h"
#include "TestModels.h"
#include "wash/translator/Analysis/ResolveFields.h"

#include <gtest/gtest.h>
#include <stdexcept>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

/// A model with its fields resolved, and their liveness.
struct Analysed {
  Model M;
  Liveness L;
  const FieldLiveness &operator[](const std::string &Name) const {
    for (unsigned I = 0; I < M.Fields.size(); ++I)
      if (M.Fields[I].Name == Name)
        return L.Fields.at(I);
    throw std::out_of_range(Name);
  }
};

Analysed analysed(Model M) {
  summarise(M);
  M.Fields = resolveFields(M.Sim.Dimension, M.Forces, M.Kernels).Fields;
  Liveness L = computeLiveness(M.Fields, M.Kernels);
  return {std::move(M), std::move(L)};
}

} // namespace

TEST(Liveness, UntouchedRegisteredForceIsDeadAndWarned) {
  Model M;
  M.Forces.push_back({"unused", ForceKind::Vector, {"sim.cpp", 7, 3}});
  Analysed A = analysed(M);
  EXPECT_FALSE(A["unused"].Live);
  ASSERT_EQ(A.L.Findings.size(), 1u);
  EXPECT_EQ(A.L.Findings[0].Id, DiagId::ForceUnused);
  EXPECT_EQ(A.L.Findings[0].Pos.Line, 7u);
}

TEST(Liveness, WrittenOnlyIsLiveOutputOnlyAndReadIsNot) {
  Model M;
  M.Forces.push_back({"w", ForceKind::Scalar, {}});
  M.Forces.push_back({"r", ForceKind::Scalar, {}});
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {force("w", ForceKind::Scalar, Mode::Write, 1), neighbour("r")}));
  Analysed A = analysed(M);
  EXPECT_TRUE(A["w"].Live);
  EXPECT_TRUE(A["w"].OutputOnly);
  EXPECT_TRUE(A["r"].Live);
  EXPECT_FALSE(A["r"].OutputOnly);
  EXPECT_TRUE(A.L.Findings.empty());
}

TEST(Liveness, OutputColumnsAlwaysLiveButAccIsNot) {
  Analysed A = analysed(Model{});
  ASSERT_EQ(A.L.Fields.size(), A.M.Fields.size());
  for (const char *F : {"id", "pos", "vel", "density", "mass", "smoothing_length"})
    EXPECT_TRUE(A[F].Live) << F;
  EXPECT_FALSE(A["acc"].Live);
}
