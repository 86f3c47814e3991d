#include "wash/translator/Analysis/Hazards.h"
#include "TestModels.h"

#include <gtest/gtest.h>

using namespace wash::tr;
using namespace wash::tr::test;

TEST(Hazards, OwnWriteAndNeighbourReadOfTheSameField) {
  Model M;
  M.Kernels.push_back(kernel(KernelKind::Force, "k",
                             {own("vel", Mode::Write), neighbour("vel"), neighbour("pos"),
                              own("density", Mode::Write), own("density", Mode::Read)}));
  summarise(M);
  std::vector<KernelHazards> H = findHazards(M.Kernels);
  EXPECT_EQ(H.at(0).Snapshot, FieldSet{"vel"});
  EXPECT_TRUE(H.at(0).DisjointTypes.empty());
}

TEST(Hazards, UpdateKernelsHaveNone) {
  Model M;
  M.Kernels.push_back(
      kernel(KernelKind::Update, "u", {own("vel", Mode::Write), own("vel", Mode::Read)}));
  summarise(M);
  std::vector<KernelHazards> H = findHazards(M.Kernels);
  EXPECT_TRUE(H.at(0).Snapshot.empty());
}

TEST(Hazards, NoneBetweenDisjointParticleTypes) {
  Model M;
  M.Kernels.push_back(
      kernel(KernelKind::Force, "walls", {own("density", Mode::Write), neighbour("density")}));
  M.Kernels[0].ParticleType = "wall";
  M.Kernels[0].NeighbourType = "fluid";
  summarise(M);
  std::vector<KernelHazards> H = findHazards(M.Kernels);
  EXPECT_TRUE(H.at(0).Snapshot.empty());
  EXPECT_EQ(H.at(0).DisjointTypes, FieldSet{"density"});
}

TEST(Hazards, KeptWhenTheTypesOverlap) {
  // The same type, or neighbours of every type: a written particle is read.
  for (const char *Neighbours : {"fluid", ""}) {
    Model M;
    M.Kernels.push_back(
        kernel(KernelKind::Force, "fluid", {own("density", Mode::Write), neighbour("density")}));
    M.Kernels[0].ParticleType = "fluid";
    M.Kernels[0].NeighbourType = Neighbours;
    summarise(M);
    std::vector<KernelHazards> H = findHazards(M.Kernels);
    EXPECT_EQ(H.at(0).Snapshot, FieldSet{"density"}) << Neighbours;
    EXPECT_TRUE(H.at(0).DisjointTypes.empty());
  }
}
