#include "wash/translator/Plan/SearchReorder.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

Kernel always(Kernel K, FieldSet Writes) {
  K.AlwaysWrites = std::move(Writes);
  return K;
}

FieldSet plan(Model &M) {
  summarise(M);
  planSearches(M);
  return planSearchReorder(M.Kernels, M.Searches);
}

} // namespace

TEST(SearchReorder, SeedShapeLeavesWhatTheForceKernelsSetFirst) {
  Model M;
  M.Kernels.push_back(
      always(kernel(KernelKind::Update, "move", {own("vel", Mode::Read), own("pos", Mode::Write)}),
             {"pos"}));
  M.Kernels.push_back(
      always(kernel(KernelKind::Force, "density", {neighbour("pos"), own("density", Mode::Write)}),
             {"density"}));
  M.Kernels.push_back(
      always(kernel(KernelKind::Force, "force",
                    {neighbour("density"), own("density", Mode::Read), own("vel", Mode::Read),
                     own("vel", Mode::Write), own("pressure", Mode::Write)}),
             {"vel", "pressure"}));
  EXPECT_EQ(plan(M), (FieldSet{"density", "pressure"})); // vel is read first
}

TEST(SearchReorder, ConditionalOrReadFirstMoves) {
  Model M;
  M.Kernels.push_back(
      kernel(KernelKind::Force, "a", {neighbour("pos"), own("density", Mode::Write)})); // maybe
  M.Kernels.push_back(
      always(kernel(KernelKind::Update, "b", {own("mass", Mode::Read), own("mass", Mode::Write)}),
             {"mass"}));
  EXPECT_EQ(plan(M), FieldSet{});
}

TEST(SearchReorder, EverySearchMustAllowIt) {
  Model M;
  M.Kernels.push_back(
      always(kernel(KernelKind::Force, "a", {own("density", Mode::Write)}), {"density"}));
  M.Kernels.push_back(
      always(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}), {"pos"}));
  // A second search, after which density is read before anything sets it.
  M.Kernels.push_back(kernel(KernelKind::Force, "b", {neighbour("density")}));
  EXPECT_EQ(M.Kernels.size(), 3u);
  EXPECT_EQ(plan(M), FieldSet{});
  ASSERT_EQ(M.Searches.size(), 2u);
}

TEST(SearchReorder, PositionsIdsAndSmoothingLengthsAlwaysMove) {
  Model M;
  M.Kernels.push_back(always(kernel(KernelKind::Force, "a",
                                    {own("pos", Mode::Write), own("smoothing_length", Mode::Write),
                                     own("heat", Mode::Write)}),
                             {"pos", "smoothing_length", "heat"}));
  EXPECT_EQ(plan(M), FieldSet{"heat"});
}
