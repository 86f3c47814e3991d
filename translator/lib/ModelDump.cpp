//===- ModelDump.cpp ------------------------------------------------------===//
#include "wash/translator/ModelDump.h"
#include "wash/translator/Analysis/ParticleTypes.h"

#include <algorithm>

namespace wash::tr {

static std::string pos(const SourcePos &P) {
  return P.valid() ? std::to_string(P.Line) + ":" + std::to_string(P.Col) : "-";
}

/// " (gas.hpp)" for a position outside the simulation's own file.
static std::string fileNote(const Model &M, const SourcePos &P) {
  if (P.File.empty() || P.File == M.SourceFile)
    return "";
  return " (" + P.File.substr(P.File.find_last_of('/') + 1) + ")";
}

/// A set in field order, so the dump does not depend on name sorting.
static void printSet(const Model &M, std::ostream &OS, const char *Label, const FieldSet &S,
                     const char *Indent = "    ", const std::string &Why = "") {
  OS << Indent << Label << ":";
  if (S.empty())
    OS << " -";
  for (const Field &F : M.Fields)
    if (S.count(F.Name))
      OS << ' ' << F.Name;
  // Names without a field appear before resolveFields ran (--dump-after) or
  // when an earlier pass failed.
  for (const std::string &N : S)
    if (!M.findField(N))
      OS << ' ' << N;
  if (!S.empty() && !Why.empty())
    OS << " (" << Why << ')';
  OS << '\n';
}

static void printSetting(std::ostream &OS, const char *Label,
                         const std::optional<SettingValue> &V) {
  OS << "  " << Label << ": ";
  if (!V)
    OS << "unset\n";
  else
    OS << (V->Constant ? "" : "runtime ") << V->Text << " @" << pos(V->Pos) << '\n';
}

static void printNames(std::ostream &OS, const char *Label, const std::vector<SettingValue> &Vs) {
  OS << "  " << Label << ":";
  if (Vs.empty())
    OS << " unset";
  for (const SettingValue &V : Vs)
    OS << ' ' << (V.Constant ? "" : "runtime ") << V.Text << " @" << pos(V.Pos);
  OS << '\n';
}

static const char *originName(FieldOrigin O) {
  switch (O) {
  case FieldOrigin::Builtin:
    return "builtin";
  case FieldOrigin::Registered:
    return "registered";
  case FieldOrigin::Created:
    return "created";
  }
  return "?";
}

/// The names of the types in S, or "-".
static std::string typeNames(const Model &M, const std::set<unsigned> &S) {
  std::string N;
  for (unsigned T : S)
    N += (N.empty() ? "" : " ") + M.Types[T].Name;
  return N.empty() ? "-" : N;
}

/// A typed simulation's field: the types kernels read and write it for, and
/// those they never read it for (its column is not needed for them).
static void printFieldTypes(const Model &M, std::ostream &OS, const FieldTypeUse &U) {
  std::set<unsigned> Unread;
  for (unsigned T = 0; T < M.Types.size(); ++T)
    if (!U.ReadFor.count(T))
      Unread.insert(T);
  OS << "    read-for: " << typeNames(M, U.ReadFor)
     << "; written-for: " << typeNames(M, U.WrittenFor)
     << "; never-read-for: " << typeNames(M, Unread) << '\n';
}

/// Why a force kernel's own writes read through neighbours need a snapshot,
/// or (Disjoint) need none: the types it writes and reads.
static std::string hazardReason(const Model &M, const Kernel &K, bool Disjoint) {
  if (!M.typed())
    return "writes own, reads neighbour";
  auto Name = [](const std::string &T) { return T.empty() ? std::string("any type") : T; };
  return "writes own " + Name(K.ParticleType) + ", reads neighbour " + Name(K.NeighbourType) +
         (Disjoint ? ": disjoint types" : "");
}

void dumpModel(const Model &M, std::ostream &OS) {
  OS << "simulation\n";
  OS << "  precision: " << M.Sim.Precision << '\n';
  OS << "  dimension: " << M.Sim.Dimension << '\n';
  printSetting(OS, "influence-radius", M.Sim.InfluenceRadius);
  printSetting(OS, "smoothing-length-support", M.Sim.SmoothingLengthSupport);
  if (M.Sim.SymmetricSupport)
    OS << "  support-rule: symmetric (pairs within k max(h_i, h_j))\n";
  printSetting(OS, "max-iterations", M.Sim.MaxIterations);
  printNames(OS, "simulation-name", M.Sim.SimulationNames);
  printNames(OS, "output-file-name", M.Sim.OutputFileNames);
  OS << "  starts: " << (M.Sim.CallsStart ? "yes" : "no") << '\n';

  if (M.typed()) {
    OS << "particle-types:";
    for (unsigned T = 0; T < M.Types.size(); ++T)
      OS << ' ' << T << '=' << M.Types[T].Name << " @" << pos(M.Types[T].Pos);
    OS << '\n';
  }
  const std::map<std::string, FieldTypeUse> TypeUses = fieldTypeUses(M.Types, M.Kernels);

  OS << "fields\n";
  for (const Field &F : M.Fields) {
    OS << "  " << F.Name << ": " << originName(F.Origin) << ' ' << forceKindName(F.Kind);
    if (F.Kind == ForceKind::Vector)
      OS << F.Dim;
    OS << (F.Live ? " live" : " dead");
    if (F.OutputOnly)
      OS << " output-only";
    if (F.ReadOnly)
      OS << " read-only";
    if (F.Origin != FieldOrigin::Builtin)
      OS << " @" << pos(F.Pos);
    OS << '\n';
    if (M.typed()) {
      auto It = TypeUses.find(F.Name);
      printFieldTypes(M, OS, It == TypeUses.end() ? FieldTypeUse{} : It->second);
    }
  }

  OS << "kernels\n";
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    const Kernel &K = M.Kernels[I];
    OS << "  " << I << ": " << kernelKindName(K.Kind) << ' ' << K.Function << " @" << pos(K.Pos)
       << '\n';
    if (M.typed() && K.Kind != KernelKind::Init && K.Kind != KernelKind::Void)
      OS << "    particle-type: " << (K.ParticleType.empty() ? "all" : K.ParticleType) << '\n';
    if (M.typed() && K.Kind == KernelKind::Force)
      OS << "    neighbour-type: " << (K.NeighbourType.empty() ? "all" : K.NeighbourType) << '\n';
    printSet(M, OS, "own-reads", K.OwnReads);
    printSet(M, OS, "own-writes", K.OwnWrites);
    if (K.Kind == KernelKind::Update || K.Kind == KernelKind::Force)
      printSet(M, OS, "always-writes", K.AlwaysWrites);
    if (K.Kind == KernelKind::Reduction)
      OS << "    reduce: " << K.ReduceOp << " into '" << K.Variable << "'\n";
    if (K.Kind != KernelKind::Force)
      continue;
    printSet(M, OS, "neighbour-reads", K.NeighbourReads);
    printSet(M, OS, "hazards", K.Hazards, "    ", hazardReason(M, K, false));
    // Only where types spared a snapshot, so that other dumps stay as they were.
    if (!K.DisjointTypeWrites.empty())
      printSet(M, OS, "no-snapshot", K.DisjointTypeWrites, "    ", hazardReason(M, K, true));
    OS << "    search: " << K.SearchGroup << '\n';
    printSet(M, OS, "halo", K.HaloFields);
    const bool Rebuilds = !K.HaloNewRowSends.empty();
    printSet(M, OS, Rebuilds ? "halo-exchange (new rows)" : "halo-exchange",
             Rebuilds ? K.HaloNewRowSends : K.HaloSends);
    if (Rebuilds)
      printSet(M, OS, "halo-exchange (rows kept from the previous search)", K.HaloSends);
    if (!K.HaloCurrent.empty())
      printSet(M, OS, "halo-not-sent", K.HaloCurrent, "    ",
               Rebuilds ? "kept rows: not written since they were last sent"
                        : "not written since they were last sent");
  }

  OS << "neighbour-searches\n";
  for (unsigned G = 0; G < M.Searches.size(); ++G) {
    OS << "  " << G << ":";
    for (unsigned I : M.Searches[G].Kernels)
      OS << ' ' << M.Kernels[I].Function;
    OS << '\n';
  }

  printSet(M, OS, "rewritten-after-search", M.RewrittenAfterSearch, "");

  OS << "neighbour-distances: " << (M.searchKeepsDistances() ? "kept by the search" : "none")
     << '\n';
  for (const DistanceUse &U : M.Distances)
    OS << "  " << U.Function << " @" << pos(U.Call) << ": " << U.List << ".distance(" << U.Neighbour
       << ") for " << U.Self << (U.SelfAlways ? "" : " if it is the own particle") << '\n';

  // Only where something is hoisted, so that other dumps stay as they were.
  if (M.Hoisted.empty())
    return;
  OS << "hoisted-per-neighbour: computed for every row before the kernel, read in its loop\n";
  for (unsigned K = 0; K < M.Kernels.size(); ++K) {
    bool Named = false;
    for (unsigned H = 0; H < M.Hoisted.size(); ++H) {
      const HoistedExpr &E = M.Hoisted[H];
      if (std::find(E.Kernels.begin(), E.Kernels.end(), K) == E.Kernels.end())
        continue;
      if (!Named)
        OS << "  " << M.Kernels[K].Function << ":\n";
      Named = true;
      OS << "    hoisted_" << H << " = " << E.Written << " @" << pos(E.Begin) << " in "
         << E.Function << fileNote(M, E.Begin) << ": depends only on constants and the fields of '" << E.Neighbour << "'";
      printSet(M, OS, "", E.Reads, "");
    }
  }
}

} // namespace wash::tr
