#include "wash/translator/Plan/NeighbourSearch.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

static SearchPlan plan(Model &M) {
  summarise(M);
  return planNeighbourSearch(M.Kernels, M.searchesBySmoothingLength());
}

TEST(NeighbourSearch, SeedShapeSharesOneSearch) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Init, "init", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "vel", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "density", {neighbour("pos")}));
  M.Kernels.push_back(kernel(KernelKind::Force, "force", {own("vel", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Update, "after", {own("vel", Mode::Write)}));
  SearchPlan P = plan(M);
  EXPECT_EQ(P.GroupOf, (std::vector<int>{-1, -1, 0, 0, -1}));
  ASSERT_EQ(P.Searches.size(), 1u);
  EXPECT_EQ(P.Searches[0].Kernels, (std::vector<unsigned>{2, 3}));
}

TEST(NeighbourSearch, PosWriteBetweenOrInsideSplits) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "a", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "b", {}));
  M.Kernels.push_back(kernel(KernelKind::Update, "u", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "c", {}));
  M.Kernels.push_back(kernel(KernelKind::Update, "v", {own("pos", Mode::Read)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "d", {}));
  EXPECT_EQ(plan(M).GroupOf, (std::vector<int>{0, 1, -1, 2, -1, 2}));
}
