#include "wash/translator/Plan/HaloExchange.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

static std::vector<KernelHalo> halos(Model &M) {
  summarise(M);
  planSearches(M);
  return planHalos(M.Kernels, M.Searches);
}

TEST(HaloExchange, PosPlusNeighbourReadsOnly) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {neighbour("density"), own("mass", Mode::Read), neighbour("heat")}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("vel", Mode::Read)}));
  std::vector<KernelHalo> H = halos(M);
  EXPECT_EQ(H[0].Fields, (FieldSet{"pos", "density", "heat"}));
  EXPECT_TRUE(H[1].Fields.empty());
}

TEST(HaloExchange, ASharedSearchSendsOnlyWhatChangedSinceTheLastSend) {
  Model M;
  // A rebuilds the halo (pos, density); B needs density again (unchanged since)
  // and nearDensity, which A wrote; C, after an update kernel moves particles,
  // rebuilds the halo again.
  M.Kernels.push_back(
      kernel(KernelKind::Force, "A", {neighbour("density"), own("nearDensity", Mode::Write)}));
  M.Kernels.push_back(
      kernel(KernelKind::Force, "B",
             {neighbour("density"), neighbour("nearDensity"), own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "C", {neighbour("vel")}));
  std::vector<KernelHalo> H = halos(M);
  // Kept rows: density, sent before B and not written since, stays current.
  EXPECT_EQ(H[0].Sends, (FieldSet{"pos"}));
  EXPECT_EQ(H[0].NewRowSends, (FieldSet{"pos", "density"}));
  EXPECT_EQ(H[1].Sends, (FieldSet{"nearDensity"}));
  EXPECT_EQ(H[3].Sends, (FieldSet{"pos", "vel"}));
  EXPECT_EQ(H[3].NewRowSends, (FieldSet{"pos", "vel", "density"}));
}

TEST(HaloExchange, AFieldTheKernelItselfWritesIsNotResentToIt) {
  Model M;
  // Both kernels read vel through neighbours; the first also writes it, so
  // the second must receive it again.
  M.Kernels.push_back(kernel(KernelKind::Force, "A", {neighbour("vel"), own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "B", {neighbour("vel")}));
  std::vector<KernelHalo> H = halos(M);
  EXPECT_EQ(H[0].Sends, (FieldSet{"pos"}));
  EXPECT_EQ(H[0].NewRowSends, (FieldSet{"pos", "vel"}));
  EXPECT_EQ(H[1].Sends, (FieldSet{"vel"}));
}

TEST(HaloExchange, AFieldOnlyInitWritesTravelsOnlyToNewRows) {
  Model M;
  // The tank: mass written at init only; density by the first kernel.
  M.Kernels.push_back(kernel(KernelKind::Init, "spawn", {own("mass", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}));
  M.Kernels.push_back(
      kernel(KernelKind::Force, "A", {neighbour("mass"), own("density", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "B", {neighbour("mass"), neighbour("density")}));
  std::vector<KernelHalo> H = halos(M);
  EXPECT_EQ(H[2].Sends, (FieldSet{"pos"}));
  EXPECT_EQ(H[2].NewRowSends, (FieldSet{"pos", "mass"}));
  EXPECT_EQ(H[2].Current, (FieldSet{"mass"}));
  EXPECT_EQ(H[3].Sends, (FieldSet{"density"}));
  EXPECT_EQ(H[3].Current, (FieldSet{"pos", "mass"}));
}

TEST(HaloExchange, NewRowsSkipAFieldWrittenBeforeItIsReadAgain) {
  Model M;
  // density is current on kept rows when A rebuilds, but A writes it before
  // B reads it: new rows need not receive it.
  M.Kernels.push_back(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}));
  M.Kernels.push_back(
      kernel(KernelKind::Force, "A", {neighbour("mass"), own("density", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "B", {neighbour("density")}));
  std::vector<KernelHalo> H = halos(M);
  EXPECT_EQ(H[1].NewRowSends, (FieldSet{"pos", "mass"}));
  EXPECT_EQ(H[2].Sends, (FieldSet{"density"}));
}
