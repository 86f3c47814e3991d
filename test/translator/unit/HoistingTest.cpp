#include "wash/translator/Analysis/Hazards.h"
#include "wash/translator/Plan/Hoisting.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

/// A model whose force kernel `Forces` (index 1) reaches one expression over
/// a neighbour's density and pressure.
Model withHoist(std::vector<Access> ForceAccesses) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Update, "Eos", {own("pressure", Mode::Write)}));
  M.Kernels.push_back(kernel(KernelKind::Force, "Forces", std::move(ForceAccesses)));
  HoistedExpr H;
  H.Begin = {"sim.cpp", 12, 20};
  H.End = {"sim.cpp", 12, 40};
  H.Function = "Forces";
  H.Neighbour = "n";
  H.Written = "sound_speed(Pj, rhoj)";
  H.Compute = {{"::sound_speed(", "", ForceKind::Scalar},
               {"", "pressure", ForceKind::Scalar},
               {", ", "", ForceKind::Scalar},
               {"", "density", ForceKind::Scalar},
               {")", "", ForceKind::Scalar}};
  H.Reads = {"density", "pressure"};
  H.Kernels = {1};
  M.Hoisted.push_back(H);
  return M;
}

std::vector<HoistedExpr> kept(Model &M) {
  summarise(M);
  std::vector<KernelHazards> Hazards = findHazards(M.Kernels);
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].Hazards = Hazards[I].Snapshot;
    M.Kernels[I].DisjointTypeWrites = Hazards[I].DisjointTypes;
  }
  return planHoists(M.Hoisted, M.Kernels);
}

} // namespace

TEST(Hoisting, KeptWhenTheKernelReadsItsFieldsThroughNeighbours) {
  Model M = withHoist({neighbour("density"), neighbour("pressure"), own("acc", Mode::Write)});
  ASSERT_EQ(kept(M).size(), 1u);
}

TEST(Hoisting, DroppedWhenAFieldIsAHazard) { // neighbours read a snapshot of it
  Model M = withHoist(
      {neighbour("density"), neighbour("pressure"), own("density", Mode::Write)});
  EXPECT_TRUE(kept(M).empty());
}

TEST(Hoisting, DroppedWhenAKernelDoesNotReadAFieldThroughNeighbours) {
  // Its copies (images, halos) would not be brought up to date before it.
  Model M = withHoist({neighbour("density"), own("pressure", Mode::Read)});
  EXPECT_TRUE(kept(M).empty());
}

TEST(Hoisting, DroppedWhenReachedByAnotherKindOfKernel) {
  Model M = withHoist({neighbour("density"), neighbour("pressure")});
  M.Hoisted[0].Kernels = {0, 1};
  EXPECT_TRUE(kept(M).empty());
}
