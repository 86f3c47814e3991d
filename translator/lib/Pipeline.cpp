//===- Pipeline.cpp - the recipe ------------------------------------------===//
//
// parse -> model -> analyse -> plan -> emit. Every pass is one function in
// its own file; this is the only place that knows their order. The model
// passes take the parts of the model they read and return what they
// compute; the recipe stores it in the model, which the dump and the
// emitters read.
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Pipeline.h"
#include "wash/translator/Analysis/ForceUses.h"
#include "wash/translator/Analysis/Hazards.h"
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Analysis/SummariseAccesses.h"
#include "wash/translator/Emit/CompileGate.h"
#include "wash/translator/Emit/EmitCMakeLists.h"
#include "wash/translator/Emit/EmitProgram.h"
#include "wash/translator/Frontend/CheckVariables.h"
#include "wash/translator/Frontend/CollectSimulation.h"
#include "wash/translator/Frontend/DetectDimension.h"
#include "wash/translator/Frontend/FindAlwaysWrites.h"
#include "wash/translator/Frontend/FindDistances.h"
#include "wash/translator/Frontend/FindHoistable.h"
#include "wash/translator/Frontend/InferAccesses.h"
#include "wash/translator/Frontend/Parse.h"
#include "wash/translator/ModelDump.h"
#include "wash/translator/Plan/HaloExchange.h"
#include "wash/translator/Plan/Hoisting.h"
#include "wash/translator/Plan/NeighbourDistances.h"
#include "wash/translator/Plan/NeighbourSearch.h"
#include "wash/translator/Plan/SearchReorder.h"

#include "llvm/ADT/Twine.h"
#include "llvm/Support/ErrorHandling.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"

#include <iterator>
#include <sstream>

namespace wash::tr {

/// Each pass's --dump-after name, indexed by PassId.
static constexpr const char *PassNames[] = {
#define WASH_PASS(Id, Name) Name,
#include "wash/translator/Passes.def"
};
static constexpr unsigned NumPasses = std::size(PassNames);
/// --dump-model prints the model after the last pass.
static constexpr PassId LastPass = static_cast<PassId>(NumPasses - 1);

const char *passName(PassId P) { return PassNames[static_cast<unsigned>(P)]; }

std::optional<PassId> findPass(std::string_view Name) {
  for (unsigned I = 0; I < NumPasses; ++I)
    if (Name == PassNames[I])
      return static_cast<PassId>(I);
  return std::nullopt;
}

std::string passNames(std::string_view Separator) {
  std::string Names;
  for (const char *Name : PassNames)
    Names += (Names.empty() ? "" : std::string(Separator)) + Name;
  return Names;
}

// Where each model pass's result goes: the dump and the emitters read it in
// the model.
static void storeAccessSets(Model &M, std::vector<AccessSets> Sets) {
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].OwnReads = std::move(Sets[I].OwnReads);
    M.Kernels[I].OwnWrites = std::move(Sets[I].OwnWrites);
    M.Kernels[I].NeighbourReads = std::move(Sets[I].NeighbourReads);
  }
}

static void storeRegistrations(Model &M, Registrations R) {
  M.Sim = std::move(R.Sim);
  M.Forces = std::move(R.Forces);
  M.Types = std::move(R.Types);
  M.Kernels = std::move(R.Kernels);
}

static void storeAlwaysWrites(Model &M, std::vector<FieldSet> Writes) {
  for (unsigned I = 0; I < M.Kernels.size(); ++I)
    M.Kernels[I].AlwaysWrites = std::move(Writes[I]);
}

static void storeFields(Model &M, ResolvedFields R) {
  M.Fields = std::move(R.Fields);
  M.Findings.insert(M.Findings.end(), R.Findings.begin(), R.Findings.end());
}

static void storeLiveness(Model &M, Liveness L) {
  for (unsigned I = 0; I < M.Fields.size(); ++I) {
    M.Fields[I].Live = L.Fields[I].Live;
    M.Fields[I].OutputOnly = L.Fields[I].OutputOnly;
  }
  M.Findings.insert(M.Findings.end(), L.Findings.begin(), L.Findings.end());
}

static void storeHazards(Model &M, std::vector<KernelHazards> Hazards) {
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].Hazards = std::move(Hazards[I].Snapshot);
    M.Kernels[I].DisjointTypeWrites = std::move(Hazards[I].DisjointTypes);
  }
}

static void storeSearchPlan(Model &M, SearchPlan P) {
  M.Searches = std::move(P.Searches);
  for (unsigned I = 0; I < M.Kernels.size(); ++I)
    M.Kernels[I].SearchGroup = P.GroupOf[I];
}

static void storeHalos(Model &M, std::vector<KernelHalo> Halos) {
  for (unsigned I = 0; I < M.Kernels.size(); ++I) {
    M.Kernels[I].HaloFields = std::move(Halos[I].Fields);
    M.Kernels[I].HaloSends = std::move(Halos[I].Sends);
    M.Kernels[I].HaloNewRowSends = std::move(Halos[I].NewRowSends);
    M.Kernels[I].HaloCurrent = std::move(Halos[I].Current);
  }
}

/// The passes that need the AST, then the model passes, up to and including
/// StopAfter (all of them without it).
static void analyse(clang::ASTContext &Ctx, Diagnoser &D, unsigned ParsedDim,
                    std::optional<PassId> StopAfter, Model &M, AstRefs &Refs) {
  // Called after each pass: every pass of Passes.def must be here, in its
  // order, or --dump-after would stop in the wrong place.
  unsigned Next = 0;
  auto Stop = [&](PassId P) {
    if (static_cast<unsigned>(P) != Next++)
      llvm::report_fatal_error("the recipe and Passes.def disagree at pass '" +
                               llvm::Twine(passName(P)) + "'");
    return P == StopAfter;
  };

  // Model: read the simulation out of the AST.
  std::optional<unsigned> Dimension = detectDimension(Ctx, D, ParsedDim);
  if (!Dimension)
    return;
  M.Sim.Dimension = *Dimension;
  if (Stop(PassId::DetectDimension))
    return;
  // Every pass that follows calls shares the index, and its one budget.
  ProgramIndex Index(Ctx);
  std::optional<Registrations> Registered = collectSimulation(Index, D, M.Sim.Dimension, Refs);
  if (!Registered)
    return;
  storeRegistrations(M, std::move(*Registered));
  if (Stop(PassId::CollectSimulation))
    return;
  if (!checkVariables(Ctx, D) || Stop(PassId::CheckVariables))
    return;
  auto Accesses = inferAccesses(Index, D, Refs, M.Kernels, M.Types);
  if (!Accesses)
    return;
  for (unsigned I = 0; I < M.Kernels.size(); ++I)
    M.Kernels[I].Accesses = std::move((*Accesses)[I]);
  std::vector<Finding> Limit = checkForceLimit(M.Forces, M.Kernels);
  M.Findings.insert(M.Findings.end(), Limit.begin(), Limit.end());
  if (!Limit.empty() || Stop(PassId::InferAccesses))
    return;
  M.Distances = findNeighbourDistances(Ctx, D);
  if (Stop(PassId::FindNeighbourDistances))
    return;
  M.Hoisted = findHoistable(Index, D, Refs, M.Kernels);
  if (Stop(PassId::FindHoistable))
    return;
  storeAlwaysWrites(M, findAlwaysWrites(Index, Refs, M.Kernels));
  if (Stop(PassId::FindAlwaysWrites))
    return;

  // Analyse: facts about fields and kernels.
  storeAccessSets(
      M, summariseAccesses(M.Kernels, M.searchesBySmoothingLength(), M.Sim.SymmetricSupport));
  if (Stop(PassId::SummariseAccesses))
    return;
  storeFields(M, resolveFields(M.Sim.Dimension, M.Forces, M.Kernels, M.typed()));
  if (Stop(PassId::ResolveFields))
    return;
  storeLiveness(M, computeLiveness(M.Fields, M.Kernels));
  if (Stop(PassId::ComputeLiveness))
    return;
  std::vector<Finding> Uses = checkForceUses(M.Fields, M.Kernels);
  M.Findings.insert(M.Findings.end(), Uses.begin(), Uses.end());
  if (Stop(PassId::CheckForceUses))
    return;
  storeHazards(M, findHazards(M.Kernels));
  if (Stop(PassId::FindHazards))
    return;

  // Plan: what the generated program must do around each kernel.
  storeSearchPlan(M, planNeighbourSearch(M.Kernels, M.searchesBySmoothingLength()));
  if (Stop(PassId::PlanNeighbourSearch))
    return;
  M.Distances = planNeighbourDistances(M.Distances, M.Sim, M.Kernels);
  if (Stop(PassId::PlanNeighbourDistances))
    return;
  M.RewrittenAfterSearch = planSearchReorder(M.Kernels, M.Searches);
  if (Stop(PassId::PlanSearchReorder))
    return;
  storeHalos(M, planHalos(M.Kernels, M.Searches));
  if (Stop(PassId::PlanHalos))
    return;
  M.Hoisted = planHoists(M.Hoisted, M.Kernels);
  Stop(PassId::PlanHoists);
  if (Next != NumPasses)
    llvm::report_fatal_error("the recipe ran fewer passes than Passes.def lists");
}

/// Runs the compile gate on Files and reports each error at the user's
/// line, else at its kernel's registration, else at the simulation's start.
static bool passesCompileGate(const std::vector<GeneratedFile> &Files, const Model &M,
                              const Options &Opts, Diagnoser &D) {
  CompileGateSetup Setup{Opts.OutputDir, Files[1].Name /* the program */, Opts.Target,
                         Opts.ExecutablePath, Opts.CompilerArgs};
  std::vector<CompileError> Errors = checkGeneratedCode(Files, Setup, M.Kernels);
  clang::SourceManager &SM = D.sourceManager();
  for (const CompileError &E : Errors) {
    clang::SourceLocation At = D.fromPos(E.Pos);
    std::string Message = E.Message;
    // Not in the user's code: say where it is.
    if (At.isInvalid()) {
      At = D.fromPos(E.Kernel);
      if (E.GeneratedLine)
        Message +=
            " (in the generated " + E.GeneratedFile + ":" + std::to_string(E.GeneratedLine) + ")";
      else if (E.Pos.valid())
        Message += " (in " + E.Pos.File + ":" + std::to_string(E.Pos.Line) + ")";
    }
    if (At.isInvalid())
      At = SM.getLocForStartOfFile(SM.getMainFileID());
    D.report(DiagId::GeneratedCodeDoesNotCompile, At, {Message});
  }
  return Errors.empty();
}

bool checkedStdout() {
  llvm::outs().flush();
  if (!llvm::outs().has_error())
    return true;
  llvm::errs() << "wash: error: cannot write to standard output: " << llvm::outs().error().message()
               << "\n";
  // Reported: the stream's destructor must not report it again.
  llvm::outs().clear_error();
  return false;
}

int runPipeline(const Options &Opts, TranslationFacts *Facts) {
  // Where to stop and print the model, if anywhere.
  std::optional<PassId> DumpAfter = Opts.DumpAfter;
  if (!DumpAfter && Opts.DumpModel)
    DumpAfter = LastPass;
  // The name reaches the generated project's files and build: refused now
  // rather than by CMake or make later.
  if (!DumpAfter)
    if (std::string Why = unbuildableStemReason(llvm::sys::path::stem(Opts.Source).str());
        !Why.empty()) {
      llvm::errs() << "wash: error: cannot translate '" << Opts.Source << "': " << Why
                   << ", which the generated project's build (CMake, make, Ninja) cannot "
                      "name: rename the file (letters, digits, spaces and ._+-() are safe)\n";
      return 1;
    }
  Model M;
  M.SourceFile = Opts.Source;
  std::vector<GeneratedFile> Files;
  std::vector<std::string> Inputs;
  std::vector<InputFile> HashedInputs;
  bool Failed = false;
  bool Parsed = parseSimulation(Opts, [&](clang::ASTContext &Ctx, Diagnoser &D, unsigned Dim,
                                          const IncludeDirectives &Includes) {
    AstRefs Refs;
    Inputs = inputFiles(Opts.Source, Includes);
    if (Facts)
      HashedInputs = hashedInputFiles(D.sourceManager(), Opts.Source, Includes);
    analyse(Ctx, D, Dim, DumpAfter, M, Refs);
    // Reported while the AST's source manager can still place them.
    for (const Finding &F : M.Findings)
      D.report(F);
    Failed = D.hasErrors() || M.hasErrors();
    // Emit: rewrite the user's code and generate the rest, still in memory.
    if (!Failed && !DumpAfter)
      Failed = !emitProgram(Ctx, D, M, Refs, Includes, Opts, Files) || D.hasErrors();
    // Check: the generated code compiles, or nothing is written.
    if (!Failed && !DumpAfter && Opts.CompileGate)
      Failed = !passesCompileGate(Files, M, Opts, D);
  });
  if (!Parsed || Failed)
    return 1;

  if (DumpAfter) {
    std::ostringstream Dump;
    dumpModel(M, Dump);
    llvm::outs() << Dump.str();
    return checkedStdout() ? 0 : 1;
  }
  // Write: only once everything succeeded, so an error leaves no partial output.
  ProjectOutput Out;
  Out.Dir = Opts.OutputDir;
  Out.Files = std::move(Files);
  Out.DepFile = Opts.DepFile;
  Out.DepTarget = Opts.OutputDir + "/" + Out.Files[1].Name; // the program
  Out.Inputs = std::move(Inputs);
  Out.Force = Opts.Force;
  std::string Error = writeOutputs(Out);
  if (!Error.empty()) {
    llvm::errs() << "wash: error: " << Error << "\n";
    return 1;
  }
  if (Facts)
    *Facts = {std::move(HashedInputs), M.Sim.Dimension};
  return 0;
}

int inspectSimulation(const Options &Opts, TranslationFacts &Facts) {
  bool Found = false;
  bool Parsed = parseSimulation(Opts, [&](clang::ASTContext &Ctx, Diagnoser &D, unsigned Dim,
                                          const IncludeDirectives &Includes) {
    Facts.Inputs = hashedInputFiles(D.sourceManager(), Opts.Source, Includes);
    if (std::optional<unsigned> Dimension = detectDimension(Ctx, D, Dim)) {
      Facts.Dimension = *Dimension;
      Found = !D.hasErrors();
    }
  });
  return Parsed && Found ? 0 : 1;
}

} // namespace wash::tr
