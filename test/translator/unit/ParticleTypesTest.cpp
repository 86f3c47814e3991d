// The model's per-type facts (issue 18): which types read and write each
// field, the type field of a typed model, and what types change in the plan.
#include "wash/translator/Analysis/ParticleTypes.h"
#include "TestModels.h"
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/ModelDump.h"
#include "wash/translator/Plan/HaloExchange.h"
#include "wash/translator/Plan/SearchReorder.h"
#include "wash/translator/WashApiTable.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

Kernel typed(Kernel K, const std::string &Type, const std::string &NeighbourType = "") {
  K.ParticleType = Type;
  K.NeighbourType = NeighbourType;
  return K;
}

/// Fluid and walls: the fluid kernels are for fluid, the walls' density
/// reads fluid neighbours only; an untyped update counts for every type.
Model damBreak() {
  Model M;
  M.Types = {{"fluid", {}}, {"wall", {}}};
  M.Kernels.push_back(
      kernel(KernelKind::Init, "build", {own("pos", Mode::Write), own(TypeField, Mode::Write)}));
  M.Kernels.push_back(typed(kernel(KernelKind::Force, "rates",
                                   {own("pos", Mode::Read), neighbour("pos"), neighbour("density"),
                                    own("acc", Mode::Write), own(TypeField, Mode::Read)}),
                            "fluid"));
  M.Kernels.push_back(typed(kernel(KernelKind::Force, "wallDensity",
                                   {own("pos", Mode::Read), neighbour("pos"), neighbour(TypeField),
                                    own("density", Mode::Write), own(TypeField, Mode::Read)}),
                            "wall", "fluid"));
  M.Kernels.push_back(typed(kernel(KernelKind::Update, "kick",
                                   {own("acc", Mode::Read), own("vel", Mode::Read),
                                    own("vel", Mode::Write), own(TypeField, Mode::Read)}),
                            "fluid"));
  M.Kernels.push_back(kernel(KernelKind::Update, "age", {own("heat", Mode::Write)}));
  summarise(M);
  planSearches(M);
  return M;
}

} // namespace

TEST(ParticleTypes, ATypedKernelReadsAndWritesForItsTypeOnly) {
  auto Uses = fieldTypeUses(damBreak().Types, damBreak().Kernels);
  EXPECT_EQ(Uses["acc"].WrittenFor, (std::set<unsigned>{0}));
  EXPECT_EQ(Uses["acc"].ReadFor, (std::set<unsigned>{0}));
  EXPECT_EQ(Uses["vel"].ReadFor, (std::set<unsigned>{0})); // never read for walls
  EXPECT_EQ(Uses["vel"].WrittenFor, (std::set<unsigned>{0}));
}

TEST(ParticleTypes, NeighbourReadsCountForTheNeighbourType) {
  auto Uses = fieldTypeUses(damBreak().Types, damBreak().Kernels);
  // rates reads density through neighbours of every type; wallDensity writes it for walls.
  EXPECT_EQ(Uses["density"].ReadFor, (std::set<unsigned>{0, 1}));
  EXPECT_EQ(Uses["density"].WrittenFor, (std::set<unsigned>{1}));
  EXPECT_EQ(Uses["pos"].ReadFor, (std::set<unsigned>{0, 1}));
}

TEST(ParticleTypes, UntypedAndInitKernelsCountForEveryType) {
  auto Uses = fieldTypeUses(damBreak().Types, damBreak().Kernels);
  EXPECT_EQ(Uses["heat"].WrittenFor, (std::set<unsigned>{0, 1}));
  EXPECT_EQ(Uses["pos"].WrittenFor, (std::set<unsigned>{0, 1}));
  EXPECT_TRUE(Uses["heat"].ReadFor.empty());
}

TEST(ParticleTypes, ATypedModelHasALiveTypeFieldAnUntypedOneNone) {
  Model M = damBreak();
  M.Fields = resolveFields(2, M.Forces, M.Kernels, /*Typed=*/true).Fields;
  const Field *T = M.findField(TypeField);
  ASSERT_NE(T, nullptr);
  EXPECT_EQ(T->Origin, FieldOrigin::Builtin);
  Liveness L = computeLiveness(M.Fields, M.Kernels);
  EXPECT_TRUE(L.Fields[T - M.Fields.data()].Live);

  Model U;
  U.Kernels.push_back(kernel(KernelKind::Update, "u", {own("vel", Mode::Write)}));
  summarise(U);
  U.Fields = resolveFields(2, U.Forces, U.Kernels).Fields;
  EXPECT_EQ(U.findField(TypeField), nullptr);
}

TEST(ParticleTypes, ANeighbourTypeFilterPutsTheTypeInTheHalo) {
  Model M = damBreak();
  std::vector<KernelHalo> H = planHalos(M.Kernels, M.Searches);
  EXPECT_TRUE(H[2].Fields.count(TypeField));  // wallDensity filters its neighbours by type
  EXPECT_FALSE(H[1].Fields.count(TypeField)); // rates reads every neighbour, not its type
}

TEST(ParticleTypes, ATypedKernelsWritesDoNotCountAsRewritingEveryParticle) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "f", {neighbour("pos"), own("heat", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("heat", Mode::Read)}));
  summarise(M);
  planSearches(M);
  M.Kernels[0].AlwaysWrites = {"heat"};
  EXPECT_EQ(planSearchReorder(M.Kernels, M.Searches), (FieldSet{"heat"}));
  M.Kernels[0].ParticleType = "fluid"; // walls keep their old heat, read later
  EXPECT_TRUE(planSearchReorder(M.Kernels, M.Searches).empty());
}

TEST(ParticleTypes, TheDumpShowsKernelTypesAndFieldTypes) {
  Model M = damBreak();
  M.Fields = resolveFields(2, M.Forces, M.Kernels, true).Fields;
  std::ostringstream OS;
  dumpModel(M, OS);
  const std::string D = OS.str();
  EXPECT_NE(D.find("particle-types: 0=fluid @- 1=wall @-\n"), std::string::npos) << D;
  EXPECT_NE(D.find("wallDensity @-\n    particle-type: wall\n    neighbour-type: fluid\n"),
            std::string::npos)
      << D;
  EXPECT_NE(D.find("  vel: builtin vector2 dead\n    read-for: fluid; written-for: fluid; "
                   "never-read-for: wall\n"),
            std::string::npos)
      << D;
}

TEST(ParticleTypes, AnUntypedDumpHasNoTypeLines) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("vel", Mode::Write)}));
  summarise(M);
  M.Fields = resolveFields(2, M.Forces, M.Kernels).Fields;
  std::ostringstream OS;
  dumpModel(M, OS);
  EXPECT_EQ(OS.str().find("type"), std::string::npos) << OS.str();
}
