#include "wash/translator/ModelDump.h"
#include "TestModels.h"
#include "wash/translator/Analysis/Hazards.h"
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Analysis/SummariseAccesses.h"
#include "wash/translator/Plan/HaloExchange.h"
#include "wash/translator/Plan/NeighbourSearch.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace wash::tr;
using namespace wash::tr::test;

TEST(ModelDump, ForceKernelSection) {
  Model M;
  M.Forces.push_back({"t", ForceKind::Scalar, {"sim.cpp", 3, 19}});
  Kernel K = kernel(KernelKind::Force, "k",
                    {neighbour("t"), force("t", ForceKind::Scalar, Mode::Write, 4)});
  K.Pos = {"sim.cpp", 9, 3};
  M.Kernels.push_back(K);
  summariseAccesses(M);
  resolveFields(M);
  computeLiveness(M);
  findHazards(M);
  planNeighbourSearch(M);
  planHalos(M);
  std::ostringstream OS;
  dumpModel(M, OS);
  std::string Out = OS.str();
  EXPECT_NE(Out.find("  t: registered scalar live @3:19\n"), std::string::npos) << Out;
  EXPECT_NE(Out.find("  0: force k @9:3\n"
                     "    own-reads: -\n"
                     "    own-writes: t\n"
                     "    always-writes: -\n"
                     "    neighbour-reads: t\n"
                     "    hazards: t\n"
                     "    search: 0\n"
                     "    halo: pos t\n"),
            std::string::npos)
      << Out;
  EXPECT_NE(Out.find("neighbour-searches\n  0: k\n"), std::string::npos) << Out;
}
