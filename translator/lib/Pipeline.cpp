//===- Pipeline.cpp - the recipe ------------------------------------------===//
//
// parse -> model -> analyse -> plan -> emit. Every pass is one function in
// its own file; this is the only place that knows their order.
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Pipeline.h"
#include "wash/translator/Analysis/Hazards.h"
#include "wash/translator/Analysis/Liveness.h"
#include "wash/translator/Analysis/ResolveFields.h"
#include "wash/translator/Analysis/SummariseAccesses.h"
#include "wash/translator/Emit/EmitProgram.h"
#include "wash/translator/Frontend/CollectSimulation.h"
#include "wash/translator/Frontend/DetectDimension.h"
#include "wash/translator/Frontend/FindAlwaysWrites.h"
#include "wash/translator/Frontend/FindDistances.h"
#include "wash/translator/Frontend/InferAccesses.h"
#include "wash/translator/Frontend/Parse.h"
#include "wash/translator/ModelDump.h"
#include "wash/translator/Plan/HaloExchange.h"
#include "wash/translator/Plan/NeighbourDistances.h"
#include "wash/translator/Plan/NeighbourSearch.h"
#include "wash/translator/Plan/SearchReorder.h"

#include "llvm/Support/raw_ostream.h"

#include <iostream>

namespace wash::tr {

/// The passes that need the AST, then the model passes, whose findings are
/// reported while the AST's source manager can still place them.
static void analyse(clang::ASTContext &Ctx, Diagnoser &D, unsigned ParsedDim, Model &M,
                    AstRefs &Refs) {
  // Model: read the simulation out of the AST.
  if (!detectDimension(Ctx, D, ParsedDim, M) || !collectSimulation(Ctx, D, M, Refs) ||
      !inferAccesses(Ctx, D, Refs, M))
    return;
  findNeighbourDistances(Ctx, D, M);
  findAlwaysWrites(Ctx, Refs, M);

  // Analyse: facts about fields and kernels.
  summariseAccesses(M);
  resolveFields(M);
  computeLiveness(M);
  findHazards(M);

  // Plan: what the generated program must do around each kernel.
  planNeighbourSearch(M);
  planNeighbourDistances(M);
  planSearchReorder(M);
  planHalos(M);

  for (const Finding &F : M.Findings)
    D.report(F);
}

int runPipeline(const Options &Opts) {
  Model M;
  M.SourceFile = Opts.Source;
  std::vector<GeneratedFile> Files;
  bool Failed = false;
  bool Parsed = parseSimulation(Opts, [&](clang::ASTContext &Ctx, Diagnoser &D, unsigned Dim) {
    AstRefs Refs;
    analyse(Ctx, D, Dim, M, Refs);
    Failed = D.hasErrors() || M.hasErrors();
    // Emit: rewrite the user's code and generate the rest, still in memory.
    if (!Failed && !Opts.DumpModel)
      Failed = !emitProgram(Ctx, D, M, Refs, Opts, Files) || D.hasErrors();
  });
  if (!Parsed || Failed)
    return 1;

  if (Opts.DumpModel) {
    dumpModel(M, std::cout);
    return std::cout.good() ? 0 : 1;
  }
  // Write: only once everything succeeded, so an error leaves no partial output.
  std::string Error = writeProject(Opts.OutputDir, Files);
  if (!Error.empty()) {
    llvm::errs() << "wash: error: " << Error << "\n";
    return 1;
  }
  return 0;
}

} // namespace wash::tr
