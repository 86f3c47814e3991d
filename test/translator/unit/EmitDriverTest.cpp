//===- EmitDriverTest.cpp - the one driver, from hand-planned models -------===//
#include "wash/translator/Emit/EmitDriver.h"
#include "wash/translator/Backends.h"
#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Emit/EmitStorage.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace wash::tr;

namespace {

Field field(const std::string &Name, ForceKind Kind = ForceKind::Scalar,
            FieldOrigin Origin = FieldOrigin::Builtin) {
  Field F;
  F.Name = Name;
  F.Kind = Kind;
  F.Origin = Origin;
  F.Live = true;
  return F;
}

Kernel kernel(KernelKind Kind, const std::string &Name, FieldSet Writes, FieldSet NeighbourReads,
              FieldSet HaloSends = {}, FieldSet Hazards = {}) {
  Kernel K;
  K.Kind = Kind;
  K.Function = Name;
  K.OwnWrites = std::move(Writes);
  K.NeighbourReads = NeighbourReads;
  K.HaloFields = NeighbourReads;
  K.HaloFields.insert("pos");
  K.HaloSends = std::move(HaloSends);
  K.Hazards = std::move(Hazards);
  return K;
}

/// The seed's shape, planned by hand: an update kernel, a force kernel that
/// searches, one that reuses its search and has a snapshot hazard (vel), and a
/// force kernel that reads nothing but positions through neighbours.
Model seedLikeModel() {
  Model M;
  M.Sim.Dimension = 2;
  for (const char *B : {"id", "pos", "vel", "density", "mass", "smoothing_length"})
    M.Fields.push_back(field(B, std::string(B) == "pos" || std::string(B) == "vel"
                                    ? ForceKind::Vector
                                    : ForceKind::Scalar));
  M.Fields.push_back(field("pressure", ForceKind::Vector, FieldOrigin::Registered));
  M.Kernels.push_back(kernel(KernelKind::Init, "::init", {"pos", "vel", "density"}, {}));
  M.Kernels.push_back(kernel(KernelKind::Update, "::move", {"pos"}, {}));
  M.Kernels.push_back(kernel(KernelKind::Force, "::density", {"density"}, {}, {"pos"}));
  M.Kernels.push_back(kernel(KernelKind::Force, "::pressure", {"pressure", "vel"},
                             {"density", "vel"}, {"density", "vel"}, {"vel"}));
  M.Kernels.push_back(kernel(KernelKind::Force, "::count", {"mass"}, {}));
  for (unsigned K : {2u, 3u, 4u})
    M.Kernels[K].SearchGroup = 0;
  M.Searches.push_back({{2, 3, 4}});
  return M;
}

std::vector<std::string> callees(const Model &M) {
  std::vector<std::string> C;
  for (const Kernel &K : M.Kernels)
    C.push_back(K.Function);
  return C;
}

std::string driverFor(const Model &M, Backend B) {
  return emitDriver(M, planCode(M, B, "sim"), callees(M));
}

std::vector<std::string> lines(const std::string &Text) {
  std::vector<std::string> L;
  std::istringstream In(Text);
  for (std::string Line; std::getline(In, Line);)
    L.push_back(Line);
  return L;
}

TEST(EmitDriver, EveryBackendGetsTheSameDriverText) {
  const Model M = seedLikeModel();
  const std::string Serial = driverFor(M, Backend::Serial);
  for (const BackendInfo &B : allBackends()) {
    std::string Text = driverFor(M, B.Id);
    const std::string Banner = "(" + std::string(B.Name) + " backend)";
    ASSERT_NE(Text.find(Banner), std::string::npos) << B.Name;
    Text.replace(Text.find(Banner), Banner.size(), "(serial backend)");
    EXPECT_EQ(Text, Serial) << B.Name;
  }
}

TEST(EmitDriver, CallsOnlyTheBackendTypeAndTheRun) {
  const std::string Text = driverFor(seedLikeModel(), Backend::MPI);
  for (const char *Spelled : {"wash::mpi", "wash::serial", "wash::openmp", "images.", "halo.",
                              "keepInitialShare", "grid.sort", "permute"})
    EXPECT_EQ(Text.find(Spelled), std::string::npos) << Spelled;
  EXPECT_NE(Text.find("backend.distribute(P, "), std::string::npos);
  EXPECT_NE(Text.find("backend.report(run);"), std::string::npos);
}

TEST(EmitDriver, SearchAndRefreshCarryWhatNeighboursReadAndSayWhy) {
  const std::string Text = driverFor(seedLikeModel(), Backend::Serial);
  EXPECT_NE(Text.find("    // Neighbours read pos.\n"
                      "    search(wash::backend::fixedGeometry(run.radius()), run.box(),\n"
                      "           [](auto send) { send(P.id); send(P.pos); },\n"
                      "           [](auto send) { send(P.id); send(P.pos); });\n"),
            std::string::npos)
      << Text;
  EXPECT_NE(Text.find("    // Neighbours read density and vel, written since they were sent.\n"
                      "    backend.refresh([](auto send) { send(P.density); send(P.vel); });\n"),
            std::string::npos)
      << Text;
  // The third kernel of the search needs nothing sent.
  EXPECT_EQ(Text.find("refresh"), Text.rfind("refresh"));
}

TEST(EmitDriver, SnapshotPointersOnlyBeforeKernelsReadingThem) {
  const std::string Text = driverFor(seedLikeModel(), Backend::Serial);
  const size_t Pressure = Text.find("// ::pressure"), Count = Text.find("// ::count");
  ASSERT_NE(Pressure, std::string::npos);
  ASSERT_NE(Count, std::string::npos);
  const size_t Snapshot = Text.find("vel_snapshot = P.vel;");
  EXPECT_GT(Snapshot, Pressure);
  EXPECT_LT(Snapshot, Count);
  EXPECT_EQ(Text.find("vel_neighbour"), Text.rfind("vel_neighbour")); // set once, for ::pressure
}

TEST(EmitDriver, NoStatementTwiceInARow) {
  for (const BackendInfo &B : allBackends()) {
    const std::vector<std::string> L = lines(driverFor(seedLikeModel(), B.Id));
    for (size_t I = 1; I < L.size(); ++I)
      if (L[I].find(';') != std::string::npos)
        EXPECT_NE(L[I], L[I - 1]) << B.Name << " line " << I;
  }
}

TEST(EmitStorage, NamesTheBackendTypeFromTheBackendsList) {
  const Model M = seedLikeModel();
  for (const BackendInfo &B : allBackends()) {
    const std::string Header = emitStorageHeader(M, planCode(M, B.Id, "sim"));
    EXPECT_NE(Header.find("#include <wash/" + std::string(B.Name) + "/backend.hpp>"),
              std::string::npos);
    EXPECT_NE(Header.find("using Backend = wash::" + std::string(B.Name) + "::Backend<2>;"),
              std::string::npos);
  }
}

} // namespace
