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
  EXPECT_EQ(findHazards(M.Kernels), std::vector<FieldSet>{FieldSet{"vel"}});
}

TEST(Hazards, UpdateKernelsHaveNone) {
  Model M;
  M.Kernels.push_back(
      kernel(KernelKind::Update, "u", {own("vel", Mode::Write), own("vel", Mode::Read)}));
  summarise(M);
  EXPECT_EQ(findHazards(M.Kernels), std::vector<FieldSet>{FieldSet{}});
}
