#include "wash/translator/ModelDump.h"
#include "TestModels.h"
#include "wash/translator/Analysis/Hazards.h"
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Plan/HaloExchange.h"

#include <gtest/gtest.h>
#include <sstream>

using namespace wash::tr;
using namespace wash::tr::test;

namespace {

/// The model passes the force kernel section shows, stored as the pipeline does.
void analyse(Model &M) {
  summarise(M);
  M.Fields = resolveFields(M.Sim.Dimension, M.Forces, M.Kernels).Fields;
  Liveness L = computeLiveness(M.Fields, M.Kernels);
  for (unsigned I = 0; I < M.Fields.size(); ++I) {
    M.Fields[I].Live = L.Fields[I].Live;
    M.Fields[I].OutputOnly = L.Fields[I].OutputOnly;
  }
  std::vector<KernelHazards> Hazards = findHazards(M.Kernels);
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].Hazards = Hazards[I].Snapshot;
    M.Kernels[I].DisjointTypeWrites = Hazards[I].DisjointTypes;
  }
  planSearches(M);
  std::vector<KernelHalo> Halos = planHalos(M.Kernels, M.Searches);
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].HaloFields = Halos[I].Fields;
    M.Kernels[I].HaloSends = Halos[I].Sends;
    M.Kernels[I].HaloNewRowSends = Halos[I].NewRowSends;
    M.Kernels[I].HaloCurrent = Halos[I].Current;
  }
}

std::string dump(const Model &M) {
  std::ostringstream OS;
  dumpModel(M, OS);
  return OS.str();
}

Model oneForceKernel() {
  Model M;
  M.Forces.push_back({"t", ForceKind::Scalar, {"sim.cpp", 3, 19}});
  Kernel K = kernel(KernelKind::Force, "k",
                    {neighbour("t"), force("t", ForceKind::Scalar, Mode::Write, 4)});
  K.Pos = {"sim.cpp", 9, 3};
  M.Kernels.push_back(K);
  return M;
}

} // namespace

TEST(ModelDump, ForceKernelSection) {
  Model M = oneForceKernel();
  analyse(M);
  std::string Out = dump(M);
  EXPECT_NE(Out.find("  t: registered scalar live @3:19\n"), std::string::npos) << Out;
  EXPECT_NE(Out.find("  0: force k @9:3\n"
                     "    own-reads: -\n"
                     "    own-writes: t\n"
                     "    always-writes: -\n"
                     "    neighbour-reads: t\n"
                     "    hazards: t (writes own, reads neighbour)\n"
                     "    search: 0\n"
                     "    halo: pos t\n"),
            std::string::npos)
      << Out;
  EXPECT_NE(Out.find("neighbour-searches\n  0: k\n"), std::string::npos) << Out;
}

// --dump-after prints models the later passes have not filled in.
TEST(ModelDump, AnEmptyModelPrintsEverySectionEmpty) {
  EXPECT_EQ(dump(Model{}), "simulation\n"
                           "  precision: double\n"
                           "  dimension: 2\n"
                           "  influence-radius: unset\n"
                           "  smoothing-length-support: unset\n"
                           "  max-iterations: unset\n"
                           "  simulation-name: unset\n"
                           "  output-file-name: unset\n"
                           "  starts: no\n"
                           "fields\n"
                           "kernels\n"
                           "neighbour-searches\n"
                           "rewritten-after-search: -\n"
                           "neighbour-distances: none\n");
}

TEST(ModelDump, SetsBeforeTheFieldsAreResolvedPrintTheirNames) {
  Model M = oneForceKernel();
  summarise(M);
  std::string Out = dump(M);
  EXPECT_EQ(Out.substr(Out.find("fields\n")), "fields\n"
                                              "kernels\n"
                                              "  0: force k @9:3\n"
                                              "    own-reads: -\n"
                                              "    own-writes: t\n"
                                              "    always-writes: -\n"
                                              "    neighbour-reads: t\n"
                                              "    hazards: -\n"
                                              "    search: -1\n"
                                              "    halo: -\n"
                                              "    halo-exchange: -\n"
                                              "neighbour-searches\n"
                                              "rewritten-after-search: -\n"
                                              "neighbour-distances: none\n");
}
