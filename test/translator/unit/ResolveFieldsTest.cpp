#include "wash/translator/Analysis/ResolveFields.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

static ResolvedFields resolve(const Model &M) {
  return resolveFields(M.Sim.Dimension, M.Forces, M.Kernels);
}

static const Field *find(const ResolvedFields &R, const std::string &Name) {
  for (const Field &F : R.Fields)
    if (F.Name == Name)
      return &F;
  return nullptr;
}

TEST(ResolveFields, CreatesUnregisteredForcesAtFirstUseInitFirst) {
  Model M;
  M.Kernels.push_back(
      kernel(KernelKind::Update, "u", {force("heat", ForceKind::Scalar, Mode::Read, 20)}));
  M.Kernels.push_back(
      kernel(KernelKind::Init, "i", {force("heat", ForceKind::Scalar, Mode::Write, 10)}));
  ResolvedFields R = resolve(M);
  const Field *F = find(R, "heat");
  ASSERT_NE(F, nullptr);
  EXPECT_EQ(F->Origin, FieldOrigin::Created);
  EXPECT_EQ(F->Pos.Line, 10u);
  ASSERT_EQ(R.Findings.size(), 1u);
  EXPECT_EQ(R.Findings[0].Id, DiagId::ForceCreated);
  EXPECT_EQ(R.Findings[0].Args, (std::vector<std::string>{"heat", "scalar"}));
}

TEST(ResolveFields, KindMismatchAgainstRegistrationIsAnErrorWithNote) {
  Model M;
  M.Sim.Dimension = 3;
  M.Forces.push_back({"p", ForceKind::Vector, {"sim.cpp", 5, 19}});
  M.Kernels.push_back(
      kernel(KernelKind::Update, "u", {force("p", ForceKind::Scalar, Mode::Read, 9)}));
  ResolvedFields R = resolve(M);
  EXPECT_EQ(find(R, "p")->Dim, 3u);
  ASSERT_EQ(R.Findings.size(), 1u);
  EXPECT_EQ(R.Findings[0].Id, DiagId::ForceKindMismatch);
  EXPECT_EQ(diagLevel(R.Findings[0].Id), DiagLevel::Error);
  EXPECT_EQ(R.Findings[0].Args, (std::vector<std::string>{"p", "vector", "scalar"}));
  ASSERT_EQ(R.Findings[0].Notes.size(), 1u);
  EXPECT_EQ(R.Findings[0].Notes[0].Id, DiagId::NoteRegisteredHere);
}

TEST(ResolveFields, BuiltinsComeFirstThenRegisteredThenCreated) {
  Model M;
  M.Forces.push_back({"b", ForceKind::Scalar, {}});
  M.Kernels.push_back(
      kernel(KernelKind::Update, "u", {force("a", ForceKind::Vector, Mode::Write, 1)}));
  std::vector<std::string> Names;
  for (const Field &F : resolve(M).Fields)
    Names.push_back(F.Name);
  EXPECT_EQ(Names, (std::vector<std::string>{"id", "pos", "vel", "acc", "density", "mass",
                                             "smoothing_length", "b", "a"}));
}
