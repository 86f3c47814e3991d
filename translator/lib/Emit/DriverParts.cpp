//===- DriverParts.cpp - pieces every generated driver shares -------------===//
#include "wash/translator/Emit/DriverParts.h"

namespace wash::tr {

void emitCreateParticle(std::ostream &OS, const CodePlan &Plan) {
  OS << "Self &create_particle(double density, double mass, double smoothing_length,\n"
     << "                      const wash::ParticleVec &pos, const wash::ParticleVec &vel) {\n"
     << "  static Self created{0};\n"
     << "  const std::size_t index = P.size();\n"
     << "  if (index >= std::size_t(std::numeric_limits<Index>::max()))\n"
     << "    throw wash::detail::RunError(\"too many particles for this program's index type\");\n"
     << "  created = Self{Index(index)};\n";
  for (const Field *F : Plan.Stored) {
    OS << "  P." << Plan.Member.at(F->Name) << ".push_back(";
    if (F->Name == "id")
      OS << "index";
    else if (F->Name == "pos" || F->Name == "vel")
      OS << "Stored(" << F->Name << ")";
    else if (F->Name == "density" || F->Name == "mass" || F->Name == "smoothing_length")
      OS << "Real(" << F->Name << ")";
    else
      OS << (F->Kind == ForceKind::Vector ? "Stored()" : "Real()");
    OS << ");\n";
  }
  OS << "  return created;\n}\n\n";
}

std::string translationText(const CodePlan &Plan) {
  return std::string("wash::backend::Translation{.backend = \"") + backendName(Plan.Target) +
         "\", .dimensions = " + std::to_string(Plan.Dim) +
         ", .floatStorage = " + (Plan.Float ? "true" : "false") +
         ", .smoothingLengthSearch = " + (Plan.SmoothingSearch ? "true" : "false") + "}";
}

void emitFrameColumns(std::ostream &OS, const CodePlan &Plan) {
  for (const Field *F : Plan.Output) {
    if (!F->Live)
      OS << "  f.zeros(\"" << F->Name << "\", " << (F->Kind == ForceKind::Vector ? Plan.Dim : 1)
         << ");\n";
    else
      OS << "  f." << (F->Kind == ForceKind::Vector ? "vector" : "scalar") << "(\"" << F->Name
         << "\", P." << Plan.Member.at(F->Name) << ");\n";
  }
}

namespace {
/// The stored fields K writes: what must stay finite (a dead write needs no check).
std::vector<std::string> checkedFields(const Kernel &K, const CodePlan &Plan) {
  std::vector<std::string> Fields;
  for (const std::string &F : K.OwnWrites)
    if (Plan.Member.count(F) && F != "id")
      Fields.push_back(F);
  return Fields;
}
} // namespace

void emitFiniteChecks(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                      const std::string &Step, const std::string &Rows, const std::string &Indent) {
  for (const std::string &F : checkedFields(K, Plan))
    OS << Indent << "run.checkFinite(P." << Plan.Member.at(F) << ", P.id, " << Rows << ", " << Step
       << ", \"" << K.Function << "\", \"" << F << "\");\n";
}

void emitParticleLoop(std::ostream &OS, const Kernel &K, unsigned KernelIndex, const CodePlan &Plan,
                      const std::string &LoopNamespace, const std::string &Rows,
                      const std::string &Callee) {
  const std::string Call =
      Callee + (K.Kind == KernelKind::Force ? "(self, " + neighbourListText(Plan) + ")" : "(self)");
  const std::vector<std::string> Checked = checkedFields(K, Plan);
  if (Checked.empty()) {
    OS << "    " << LoopNamespace << "::forEachParticle(" << Rows << ", [](Index i) {\n"
       << "      Self self{i};\n"
       << "      " << Call << ";\n"
       << "    });\n";
    emitWrap(OS, K, Rows, "    ");
    return;
  }
  const std::string Finite = "wroteFinite" + std::to_string(KernelIndex);
  OS << "    const bool " << Finite << " = " << LoopNamespace << "::forEachParticleChecked(" << Rows
     << ", [](Index i) {\n"
     << "      Self self{i};\n"
     << "      " << Call << ";\n"
     << "      return";
  for (unsigned F = 0; F < Checked.size(); ++F)
    OS << (F ? " &\n             " : " ") << "wash::backend::finite(P."
       << Plan.Member.at(Checked[F]) << "[i])";
  OS << ";\n"
     << "    });\n";
  emitWrap(OS, K, Rows, "    ");
  OS << "    if (!" << Finite << ") {\n";
  emitFiniteChecks(OS, K, Plan, "step", Rows, "      ");
  OS << "    }\n";
}

void emitWrap(std::ostream &OS, const Kernel &K, const std::string &Rows,
              const std::string &Indent) {
  if (K.OwnWrites.count("pos"))
    OS << Indent << "wash::backend::wrapPositions(P.pos, " << Rows << ", run.box());\n";
}

std::string columnsVisitor(const CodePlan &Plan, const std::vector<std::string> &Fields) {
  std::string V = "[](auto send) {";
  for (const std::string &F : Fields)
    V += " send(P." + Plan.Member.at(F) + ");";
  return V + " }";
}

std::string columnsVisitor(const CodePlan &Plan, const FieldSet &Fields) {
  return columnsVisitor(Plan, std::vector<std::string>(Fields.begin(), Fields.end()));
}

void emitReduction(std::ostream &OS, const Kernel &K, const std::string &Callee,
                   const std::string &Loop, const std::string &Rows, const std::string &Reduce) {
  std::string Op = K.ReduceOp == "sum" ? "Sum" : K.ReduceOp == "min" ? "Min" : "Max";
  OS << "    {\n"
     << "      static std::vector<double> values;\n"
     << "      values.assign(P.size(), 0.0);\n"
     << "      " << Loop << "(" << Rows << ", [](Index i) {\n"
     << "        Self self{i};\n"
     << "        values[i] = " << Callee << "(self);\n"
     << "      });\n"
     << "      wash::set_variable(\"" << K.Variable << "\", " << Reduce << "(P.id, values, " << Rows
     << ", wash::detail::ReduceOp::" << Op << "));\n"
     << "    }\n";
}

void emitIterations(std::ostream &OS, const Model &M,
                    const std::function<void(unsigned)> &EmitKernel) {
  OS << "  for (std::uint64_t step = 1; step <= run.steps(); ++step) {\n";
  for (unsigned K = 0; K < M.Kernels.size(); ++K)
    if (M.Kernels[K].Kind != KernelKind::Init)
      EmitKernel(K);
  OS << "    run.endStep(step, frame);\n"
     << "  }\n";
}

std::string searchGeometryText(const CodePlan &Plan, const Kernel &K, const std::string &Rows,
                               const std::string &GlobalMax) {
  if (!Plan.SmoothingSearch)
    return "wash::backend::fixedGeometry(run.radius())";
  return "wash::backend::smoothingGeometry(run.support(), " + Plan.readColumn("smoothing_length") +
         ", P.id, " + Rows + ", run.box(), " + std::to_string(Plan.Dim) + ", step, \"" +
         K.Function + "\"" + (GlobalMax.empty() ? "" : ", " + GlobalMax) + ")";
}

std::string neighbourTableDeclaration(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "";
  return "wash::backend::NeighbourTable<" + std::to_string(Plan.Dim) +
         ", Stored> table; // the lists of the current search\n";
}

std::string neighbourTableBuild(const CodePlan &Plan, const std::string &Rows) {
  if (!Plan.SmoothingSearch)
    return "";
  return "  table.build(grid, P.pos, P.id, " + Plan.readColumn("smoothing_length") + ", at, " +
         Rows + ");\n";
}

std::string neighbourListText(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "NeighbourList(grid, P.pos, i)";
  return "table.list(i)";
}

std::string kernelComment(const Model &M, unsigned K) {
  const Kernel &Kn = M.Kernels[K];
  std::string C = "// " + Kn.Function + ": " + kernelKindName(Kn.Kind) + " kernel";
  if (Kn.Kind == KernelKind::Force) {
    const SearchGroup &G = M.Searches.at(Kn.SearchGroup);
    C += G.Kernels.front() == K
             ? ", new neighbour search"
             : ", reuses the neighbour search of '" + M.Kernels[G.Kernels.front()].Function + "'";
  }
  return C;
}

void emitSnapshots(std::ostream &OS, const Kernel &K, const CodePlan &Plan) {
  for (const std::string &F : Plan.Snapshotted) {
    const std::string &Col = Plan.Member.at(F);
    if (K.Hazards.count(F))
      OS << "    " << Col << "_snapshot = P." << Col
         << "; // written here, read through neighbours\n"
         << "    " << Col << "_neighbour = " << Col << "_snapshot.data();\n";
    else
      OS << "    " << Col << "_neighbour = P." << Col << ".data();\n";
  }
}

} // namespace wash::tr
