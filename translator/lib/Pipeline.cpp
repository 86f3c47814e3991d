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
#include "wash/translator/Frontend/CollectSimulation.h"
#include "wash/translator/Frontend/DetectDimension.h"
#include "wash/translator/Frontend/InferAccesses.h"
#include "wash/translator/Frontend/Parse.h"
#include "wash/translator/ModelDump.h"
#include "wash/translator/Plan/HaloExchange.h"
#include "wash/translator/Plan/NeighbourSearch.h"

#include "llvm/Support/raw_ostream.h"

#include <iostream>

namespace wash::tr {

const char *backendName(Backend B) {
  switch (B) {
  case Backend::Serial:
    return "serial";
  case Backend::OpenMP:
    return "openmp";
  case Backend::MPI:
    return "mpi";
  }
  return "?";
}

/// The passes that need the AST, then the model passes, whose findings are
/// reported while the AST's source manager can still place them.
static void analyse(clang::ASTContext &Ctx, Diagnoser &D, unsigned ParsedDim, Model &M) {
  // Model: read the simulation out of the AST.
  AstRefs Refs;
  if (!detectDimension(Ctx, D, ParsedDim, M) || !collectSimulation(Ctx, D, M, Refs) ||
      !inferAccesses(Ctx, D, Refs, M))
    return;

  // Analyse: facts about fields and kernels.
  summariseAccesses(M);
  resolveFields(M);
  computeLiveness(M);
  findHazards(M);

  // Plan: what the generated program must do around each kernel.
  planNeighbourSearch(M);
  planHalos(M);

  for (const Finding &F : M.Findings)
    D.report(F);
}

int runPipeline(const Options &Opts) {
  Model M;
  M.SourceFile = Opts.Source;
  bool Failed = false;
  bool Parsed = parseSimulation(Opts, [&](clang::ASTContext &Ctx, Diagnoser &D, unsigned Dim) {
    analyse(Ctx, D, Dim, M);
    Failed = D.hasErrors() || M.hasErrors();
  });
  if (!Parsed || Failed)
    return 1;

  if (Opts.DumpModel) {
    dumpModel(M, std::cout);
    return std::cout.good() ? 0 : 1;
  }
  // Emit: the next stage of the project.
  llvm::errs() << "wash: error: code generation for the '" << backendName(Opts.Target)
               << "' backend is not implemented yet; use --dump-model\n";
  return 1;
}

} // namespace wash::tr
