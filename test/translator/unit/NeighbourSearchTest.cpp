#include "wash/translator/Plan/NeighbourSearch.h"
#include "TestModels.h"
#include "wash/translator/Analysis/SummariseAccesses.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

static std::vector<int> groups(Model &M) {
  summariseAccesses(M);
  planNeighbourSearch(M);
  std::vector<int> G;
  for (const Kernel &K : M.Kernels)
    G.push_back(K.SearchGroup);
  return G;
}

TEST(NeighbourSearch, SeedShapeSharesOneSearch) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Init, "init", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "vel", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "density", {neighbour("pos")}));
  M.Kernels.push_back(kernel(KernelKind::Force, "force", {own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "after", {own("vel", Mode::Write)}));
  EXPECT_EQ(groups(M), (std::vector<int>{-1, -1, 0, 0, -1}));
  ASSERT_EQ(M.Searches.size(), 1u);
  EXPECT_EQ(M.Searches[0].Kernels, (std::vector<unsigned>{2, 3}));
}

TEST(NeighbourSearch, PosWriteBetweenOrInsideSplits) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "a", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "b", {}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "c", {}));
  M.Kernels.push_back(kernel(KernelKind::Update, "v", {own("pos", Mode::Read)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "d", {}));
  EXPECT_EQ(groups(M), (std::vector<int>{0, 1, -1, 2, -1, 2}));
}
