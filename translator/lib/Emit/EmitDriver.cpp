//===- EmitDriver.cpp - the run of a generated program, for every backend -===//
//
// The driver follows the model's plan step by step: a new neighbour search
// before the first force kernel of each search group, carrying the columns
// its neighbours read; before a later one, a refresh of those written since;
// a snapshot copy only of the fields a force kernel writes on its particle
// and reads through neighbours; and a finiteness check of what each kernel
// wrote. Every call goes to `backend` (the backend type) or `run`.
//
//===----------------------------------------------------------------------===//
#include "wash/translator/Emit/EmitDriver.h"
#include "wash/translator/Emit/DriverParts.h"
#include "wash/translator/Emit/RuntimeNames.h"
#include "wash/translator/WashApiTable.h"

#include <sstream>

namespace wash::tr {
namespace {

/// The columns the new search before K carries to the copies neighbours read
/// (periodic images, halos): ids and positions, to find and order
/// neighbours, and Sends (to halo rows kept from the previous search,
/// Kernel::HaloSends, or to new ones, Kernel::HaloNewRowSends).
std::vector<std::string> searchColumns(const FieldSet &Sends) {
  std::vector<std::string> Columns = {"id", "pos"};
  for (const std::string &F : Sends)
    if (F != "pos" && F != "id")
      Columns.push_back(F);
  return Columns;
}

void emitForceSetUp(std::ostream &OS, const Model &M, const CodePlan &Plan, unsigned K) {
  const Kernel &Kn = M.Kernels[K];
  if (M.Searches.at(Kn.SearchGroup).Kernels.front() == K) {
    std::vector<std::string> NeighbourReads(Kn.HaloFields.begin(), Kn.HaloFields.end());
    OS << "    // Neighbours read " << fieldList(NeighbourReads) << ".\n"
       << "    search(" << searchGeometryText(Plan, Kn) << ", run.box(),\n"
       << "           " << columnsVisitor(Plan, searchColumns(Kn.HaloSends)) << ",\n"
       << "           " << columnsVisitor(Plan, searchColumns(Kn.HaloNewRowSends)) << ");\n";
  } else if (!Kn.HaloSends.empty()) {
    std::vector<std::string> Sends(Kn.HaloSends.begin(), Kn.HaloSends.end());
    OS << "    // Neighbours read " << fieldList(Sends) << ", written since they were sent.\n"
       << "    backend.refresh(" << columnsVisitor(Plan, Sends) << ");\n";
  }
  emitSnapshots(OS, Kn, Plan);
}

void emitKernel(std::ostream &OS, const Model &M, const CodePlan &Plan, unsigned K,
                const std::string &Callee) {
  const Kernel &Kn = M.Kernels[K];
  OS << "    run.kernel(" << stringLiteral(Kn.Function) << "); // its time begins (--profile)\n"
     << "    " << kernelComment(M, K) << "\n";
  switch (Kn.Kind) {
  case KernelKind::Void: // every process runs it, as every process ran main
    OS << "    " << Callee << "();\n";
    return;
  case KernelKind::Reduction:
    return emitReduction(OS, Kn, Plan, Callee);
  case KernelKind::Force:
    emitForceSetUp(OS, M, Plan, K);
    emitHoistedColumns(OS, Plan, K);
    break;
  case KernelKind::Init:
  case KernelKind::Update:
    break;
  }
  emitParticleLoop(OS, Kn, K, Plan, Callee);
  if (Kn.OwnWrites.count(TypeField))
    OS << typeRowsRebuild(Plan, "    ");
}

void emitStart(std::ostream &OS, const Model &M, const CodePlan &Plan,
               const std::vector<std::string> &Callees) {
  OS << "void start() {\n"
     << "  const " << translationText(Plan, programIdentityText(M, Plan)) << "  " << rt::Run
     << " run(translated, backend.writes());\n";
  if (!Plan.Variables.empty()) {
    OS << "  " << rt::BindVariables << "({";
    for (size_t V = 0; V < Plan.Variables.size(); ++V)
      OS << (V ? ", &" : "&") << CodePlan::variableSlot(Plan.Variables[V]);
    OS << "});\n";
  }
  OS << "  std::uint64_t particles = 0;\n"
     << "  if (run.restarting()) { // the particles and the run's state from a checkpoint\n"
     << "    particles = " << rt::RestoreCheckpoint << "(backend, run, P, checkpointColumns, "
     << domainCellSizeText(Plan) << ");\n"
     << "  } else {\n";
  for (unsigned K = 0; K < M.Kernels.size(); ++K)
    if (M.Kernels[K].Kind == KernelKind::Init)
      OS << "    " << Callees[K] << "(); // init kernel\n";
  OS << "    // Each process keeps its share of what the init kernels created (they\n"
     << "    // run on every process, so they must be deterministic).\n"
     << "    particles = backend.distribute(P, " << domainCellSizeText(Plan) << ");\n";
  for (unsigned K = 0; K < M.Kernels.size(); ++K)
    if (M.Kernels[K].Kind == KernelKind::Init) {
      emitWrap(OS, M.Kernels[K], "    ");
      emitFiniteChecks(OS, M.Kernels[K], Plan, "0", "    ");
    }
  OS << "    run.begin(particles, frame);\n"
     << "  }\n";
  OS << typeRowsRebuild(Plan, "  ");
  OS << "  for (std::uint64_t step = run.firstStep(); step <= run.steps(); ++step) {\n";
  for (unsigned K = 0; K < M.Kernels.size(); ++K)
    if (M.Kernels[K].Kind != KernelKind::Init)
      emitKernel(OS, M, Plan, K, Callees[K]);
  OS << "    run.endStep(step, frame);\n"
     << "    " << rt::CheckpointAfterStep << "(backend, run, step, particles, checkpointColumns);\n"
     << "  }\n"
     << "  run.finish(frame());\n"
     << "  backend.report(run);\n"
     << "}\n";
}

} // namespace

std::string emitDriver(const Model &M, const CodePlan &Plan,
                       const std::vector<std::string> &Callees) {
  std::ostringstream OS;
  OS << "\n// ===== The run, generated by wash (" << backendName(Plan.Target)
     << " backend) =====\n\n"
     << "namespace wash_gen {\nnamespace {\n"
     << "Backend backend; // which rows are real particles, the cell grid, images, halos\n"
     << neighbourTableDeclaration(Plan) << typeRowsDeclaration(Plan) << "\n";
  emitParticleBytes(OS, Plan);
  OS << "/// A neighbour search (docs/semantics.md): `kept` and `fresh` visit the\n"
     << "/// columns the copies neighbours read (periodic images, halos) must carry:\n"
     << "/// to halo rows kept from the previous search, and to the others.\n"
     << "template <typename Kept, typename Fresh>\n"
     << "void search(const " << rt::SearchGeometry << " &at, const " << rt::Box << " &box,\n"
     << "            Kept kept, Fresh fresh) {\n"
     << "  try {\n"
     << "    backend.search(P, at, box, " << rt::HaloColumns << "<Kept, Fresh>{kept, fresh}"
     << smoothingLengthAccessor(Plan) << ");\n"
     << neighbourTableBuild(Plan) << typeRowsRebuild(Plan, "    ")
     << "  } catch (const std::bad_alloc &) {\n"
     << "    throw " << rt::OutOfMemory
     << "(\"the neighbour search (cell sort, images, lists)\", P.size(), particleBytes);\n"
     << "  }\n}\n\n"
     << "/// Every particle's output columns, on the process that writes them.\n"
     << rt::Frame << " frame() {\n"
     << "  " << rt::FrameBuilder << " f(" << Plan.Dim << ", P.id, &backend.owned());\n";
  emitFrameColumns(OS, Plan);
  OS << "  return backend.gather(f.take());\n}\n\n";
  emitCheckpointColumns(OS, Plan);
  OS << "} // namespace\n\n";
  emitCreateParticle(OS, Plan);
  emitStart(OS, M, Plan, Callees);
  OS << "} // namespace wash_gen\n";
  return OS.str();
}

} // namespace wash::tr
