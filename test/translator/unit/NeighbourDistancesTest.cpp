#include "wash/translator/Plan/NeighbourDistances.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

/// A model with one distance use found in its force kernel.
Model withUse(std::vector<Access> ForceAccesses) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Update, "move", {own("pos", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "density", std::move(ForceAccesses)));
  DistanceUse U;
  U.Call = {"sim.cpp", 12, 20};
  U.Function = "density";
  U.List = "ns";
  U.Neighbour = "n";
  U.Self = "p";
  U.SelfAlways = true;
  M.Distances.push_back(U);
  return M;
}

std::vector<DistanceUse> kept(Model &M) {
  summarise(M);
  return planNeighbourDistances(M.Distances, M.Sim, M.Kernels);
}

} // namespace

TEST(NeighbourDistances, KeptForDoublePositionsAndOneRadius) {
  Model M = withUse({neighbour("pos"), own("density", Mode::Write)});
  EXPECT_EQ(kept(M).size(), 1u);
}

TEST(NeighbourDistances, DroppedForFloatPositions) { // the user's magnitude is then float
  Model M = withUse({neighbour("pos")});
  M.Sim.Precision = "float";
  EXPECT_TRUE(kept(M).empty());
}

TEST(NeighbourDistances, DroppedForTheSmoothingLengthRule) {
  Model M = withUse({neighbour("pos")});
  M.Sim.SmoothingLengthSupport = SettingValue{"2.0", true, {}};
  EXPECT_TRUE(kept(M).empty());
}

TEST(NeighbourDistances, DroppedWhenAForceKernelMovesItsParticle) {
  Model M = withUse({neighbour("pos"), own("pos", Mode::Write)});
  EXPECT_TRUE(kept(M).empty());
}

TEST(NeighbourDistances, NoneFoundNoneKept) {
  Model M = withUse({neighbour("pos")});
  M.Distances.clear();
  EXPECT_TRUE(kept(M).empty());
}
