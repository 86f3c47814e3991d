#include "wash/translator/Plan/HaloExchange.h"
#include "TestModels.h"
#include "wash/translator/Analysis/SummariseAccesses.h"
#include "wash/translator/Plan/NeighbourSearch.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

TEST(HaloExchange, PosPlusNeighbourReadsOnly) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {neighbour("density"), own("mass", Mode::Read), neighbour("heat")}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("vel", Mode::Read)}));
  summariseAccesses(M);
  planNeighbourSearch(M);
  planHalos(M);
  EXPECT_EQ(M.Kernels[0].HaloFields, (FieldSet{"pos", "density", "heat"}));
  EXPECT_TRUE(M.Kernels[1].HaloFields.empty());
}

TEST(HaloExchange, ASharedSearchSendsOnlyWhatChangedSinceTheLastSend) {
  Model M;
  // A rebuilds the halo (pos, density); B needs density again (unchanged since)
  // and nearDensity, which A wrote; C, after an update kernel moves particles,
  // rebuilds the halo again.
  M.Kernels.push_back(kernel(KernelKind::Force, "A",
                             {neighbour("density"), own("nearDensity", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "B",
                             {neighbour("density"), neighbour("nearDensity"),
                              own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "C", {neighbour("vel")}));
  summariseAccesses(M);
  planNeighbourSearch(M);
  planHalos(M);
  EXPECT_EQ(M.Kernels[0].HaloSends, (FieldSet{"pos", "density"}));
  EXPECT_EQ(M.Kernels[1].HaloSends, (FieldSet{"nearDensity"}));
  EXPECT_EQ(M.Kernels[3].HaloSends, (FieldSet{"pos", "vel"}));
}

TEST(HaloExchange, AFieldTheKernelItselfWritesIsNotResentToIt) {
  Model M;
  // Both kernels read vel through neighbours; the first also writes it, so
  // the second must receive it again.
  M.Kernels.push_back(kernel(KernelKind::Force, "A", {neighbour("vel"), own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "B", {neighbour("vel")}));
  summariseAccesses(M);
  planNeighbourSearch(M);
  planHalos(M);
  EXPECT_EQ(M.Kernels[0].HaloSends, (FieldSet{"pos", "vel"}));
  EXPECT_EQ(M.Kernels[1].HaloSends, (FieldSet{"vel"}));
}
