#include "wash/translator/Plan/HaloExchange.h"
#include "TestModels.h"
#include "wash/translator/Analysis/SummariseAccesses.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

TEST(HaloExchange, PosPlusNeighbourReadsOnly) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {neighbour("density"), own("mass", Mode::Read), neighbour("heat")}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("vel", Mode::Read)}));
  summariseAccesses(M);
  planHalos(M);
  EXPECT_EQ(M.Kernels[0].HaloFields, (FieldSet{"pos", "density", "heat"}));
  EXPECT_TRUE(M.Kernels[1].HaloFields.empty());
}
