//===- DriverParts.cpp - the pieces of the generated driver ---------------===//
#include "wash/translator/Emit/DriverParts.h"
#include "wash/translator/Emit/RuntimeNames.h"
#include "wash/translator/WashApiTable.h"

#include <algorithm>

namespace wash::tr {

std::string translationText(const CodePlan &Plan, const std::string &Program) {
  return rt::Translation +
         " translated{.backend = Backend::name, .dimensions = " + std::to_string(Plan.Dim) +
         ",\n      .floatStorage = " + (Plan.Float ? "true" : "false") +
         ", .smoothingLengthSearch = " + (Plan.SmoothingSearch ? "true" : "false") +
         ", .symmetricSupport = " + (Plan.SymmetricSearch ? "true" : "false") +
         (Program.empty() ? "" : ",\n      .program = " + stringLiteral(Program)) + "};\n";
}

std::string programIdentityText(const Model &M, const CodePlan &Plan) {
  std::string T = "kernels:";
  for (const Kernel &K : M.Kernels)
    T += " " + std::string(kernelKindName(K.Kind)) + " " + K.Function + ";";
  T += " columns:";
  for (const Field *F : Plan.Stored)
    T += " " + F->Name;
  return T;
}

void emitCheckpointColumns(std::ostream &OS, const CodePlan &Plan) {
  OS << "/// Every stored column by name: what a checkpoint holds.\n"
     << "const auto checkpointColumns = [](auto f) {\n";
  for (const Field *F : Plan.Stored)
    OS << "  f(" << stringLiteral(F->Name) << ", P." << Plan.Member.at(F->Name) << ");\n";
  OS << "};\n\n";
}

void emitParticleBytes(std::ostream &OS, const CodePlan &Plan) {
  OS << "/// The bytes of one particle's stored columns, for out-of-memory messages.\n"
     << "constexpr std::size_t particleBytes = 0";
  for (const Field *F : Plan.Stored)
    OS << "\n    + sizeof(P." << Plan.Member.at(F->Name) << "[0])";
  OS << ";\n\n";
}

void emitCreateParticle(std::ostream &OS, const CodePlan &Plan) {
  OS << "Self &create_particle(double density, double mass, double smoothing_length,\n"
     << "                      const wash::ParticleVec &pos, const wash::ParticleVec &vel) {\n"
     << "  static Self created{0};\n"
     << "  // The id is the creation index on every backend; a distributed one\n"
     << "  // keeps this row only if the particle is this process's (create).\n"
     << "  const std::uint64_t id = backend.create(P, density, mass, smoothing_length, pos, "
        "vel);\n"
     << "  const std::size_t index = P.size();\n"
     << "  if (index >= std::size_t(std::numeric_limits<Index>::max()))\n"
     << "    throw " << rt::RunError << "(\"too many particles for this program's index type\");\n"
     << "  created = Self{Index(index)};\n"
     << "  try {\n";
  for (const Field *F : Plan.Stored) {
    // The builtins create_particle sets take its parameter of the same name
    // (WashApi.def); everything else starts at zero.
    const BuiltinField *B = F->Origin == FieldOrigin::Builtin ? builtinField(F->Name) : nullptr;
    const std::string Type = F->Kind == ForceKind::Vector ? "Stored" : "Real";
    OS << "    P." << Plan.Member.at(F->Name) << ".push_back(";
    if (B && B->Kind == FieldKind::Id)
      OS << "id";
    else if (F->Origin == FieldOrigin::Builtin && F->Name == TypeField)
      OS << "0u"; // the first type added
    else
      OS << Type << "(" << (B && B->Created ? F->Name : "") << ")";
    OS << ");\n";
  }
  // Out of memory says how much the store needed (a bare std::bad_alloc does not).
  OS << "  } catch (const std::bad_alloc &) {\n"
     << "    throw " << rt::OutOfMemory
     << "(\"the particle store (create_particle)\", index + 1, particleBytes);\n  }\n"
     << "  return created;\n}\n\n";
}

void emitFrameColumns(std::ostream &OS, const CodePlan &Plan) {
  for (const Field *F : Plan.Output) {
    if (!F->Live)
      OS << "  f.zeros(\"" << F->Name << "\", " << (F->Kind == ForceKind::Vector ? Plan.Dim : 1)
         << ");\n";
    else
      OS << "  f." << (F->Kind == ForceKind::Vector ? "vector" : "scalar") << "(\"" << F->Name
         << "\", P." << Plan.Member.at(F->Name) << ");\n";
    if (F->Name == "vel") { // acc follows, in frames only (the reference's order)
      if (Plan.Member.count("acc"))
        OS << "  f.vector(\"acc\", P." << Plan.Member.at("acc") << ");\n";
      else
        OS << "  f.zeros(\"acc\", " << Plan.Dim << ");\n";
      OS << "  f.frameOnly();\n";
    }
  }
  if (!Plan.Types.empty()) {
    OS << "  f.typeNames({";
    for (size_t T = 0; T < Plan.Types.size(); ++T)
      OS << (T ? ", " : "") << stringLiteral(Plan.Types[T]);
    OS << "});\n";
  }
}

namespace {
/// The stored fields K writes: what must stay finite (a dead write needs no check).
std::vector<std::string> checkedFields(const Kernel &K, const CodePlan &Plan) {
  std::vector<std::string> Fields;
  for (const std::string &F : K.OwnWrites)
    if (Plan.Member.count(F) && F != "id" && F != TypeField)
      Fields.push_back(F);
  return Fields;
}
} // namespace

void emitFiniteChecks(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                      const std::string &Step, const std::string &Indent) {
  for (const std::string &F : checkedFields(K, Plan))
    OS << Indent << "run.checkFinite(P." << Plan.Member.at(F) << ", P.id, backend.owned(), " << Step
       << ", \"" << K.Function << "\", \"" << F << "\");\n";
}

std::string typeRowsDeclaration(const CodePlan &Plan) {
  if (!Plan.RestrictsKernels)
    return "";
  return rt::TypeRows + " typeRows(" + std::to_string(Plan.Types.size()) +
         "); // the real particles of each type\n";
}

std::string typeRowsRebuild(const CodePlan &Plan, const std::string &Indent) {
  if (!Plan.RestrictsKernels)
    return "";
  return Indent + "typeRows.rebuild(P." + Plan.Member.at(TypeField) + ", backend.owned());\n";
}

std::string kernelRows(const CodePlan &Plan, const Kernel &K) {
  if (K.ParticleType.empty())
    return "";
  return "typeRows.of(" + std::to_string(Plan.typeIndex(K.ParticleType)) + "), ";
}

void emitParticleLoop(std::ostream &OS, const Kernel &K, unsigned KernelIndex, const CodePlan &Plan,
                      const std::string &Callee) {
  const std::string Call =
      Callee +
      (K.Kind == KernelKind::Force ? "(self, " + neighbourListText(Plan, K) + ")" : "(self)");
  const std::vector<std::string> Checked = checkedFields(K, Plan);
  const std::string Rows = kernelRows(Plan, K), In = Rows.empty() ? "" : "In";
  if (Checked.empty()) {
    OS << "    backend.forEachParticle" << In << "(" << Rows << "[](Index i) {\n"
       << "      Self self{i};\n"
       << "      " << Call << ";\n"
       << "    });\n";
    emitWrap(OS, K, "    ");
    return;
  }
  const std::string Finite = "wroteFinite" + std::to_string(KernelIndex);
  OS << "    const bool " << Finite << " = backend.forEachParticleChecked" << In << "(" << Rows
     << "[](Index i) {\n"
     << "      Self self{i};\n"
     << "      " << Call << ";\n"
     << "      return";
  for (unsigned F = 0; F < Checked.size(); ++F)
    OS << (F ? " &\n             " : " ") << rt::Finite << "(P." << Plan.Member.at(Checked[F])
       << "[i])";
  OS << ";\n"
     << "    });\n";
  emitWrap(OS, K, "    ");
  OS << "    if (!" << Finite << ") {\n";
  emitFiniteChecks(OS, K, Plan, "step", "      ");
  OS << "    }\n";
}

void emitWrap(std::ostream &OS, const Kernel &K, const std::string &Indent) {
  if (K.OwnWrites.count("pos"))
    OS << Indent << rt::WrapPositions << "(P.pos, backend.owned(), run.box());\n";
}

std::string columnsVisitor(const CodePlan &Plan, const std::vector<std::string> &Fields) {
  std::string V = "[](auto send) {";
  for (const std::string &F : Fields)
    V += " send(P." + Plan.Member.at(F) + ");";
  return V + " }";
}

std::string fieldList(const std::vector<std::string> &Fields) {
  std::string L;
  for (size_t I = 0; I < Fields.size(); ++I)
    L += (I == 0 ? "" : I + 1 == Fields.size() ? " and " : ", ") + Fields[I];
  return L;
}

std::string stringLiteral(const std::string &S) {
  std::string L = "\"";
  for (char C : S) {
    if (C == '"' || C == '\\')
      L += '\\';
    if (C >= 0x20 && C < 0x7f) {
      L += C;
      continue;
    }
    const char *Octal = "01234567";
    unsigned char U = static_cast<unsigned char>(C);
    L += {'\\', Octal[U >> 6], Octal[(U >> 3) & 7], Octal[U & 7]};
  }
  return L + "\"";
}

void emitReduction(std::ostream &OS, const Kernel &K, const CodePlan &Plan,
                   const std::string &Callee) {
  std::string Op = K.ReduceOp == "sum" ? "Sum" : K.ReduceOp == "min" ? "Min" : "Max";
  const std::string Rows = kernelRows(Plan, K), In = Rows.empty() ? "" : "In";
  OS << "    {\n"
     << "      static std::vector<double> values;\n"
     << "      values.assign(P.size(), 0.0);\n"
     << "      backend.forEachParticle" << In << "(" << Rows << "[](Index i) {\n"
     << "        Self self{i};\n"
     << "        values[i] = " << Callee << "(self);\n"
     << "      });\n"
     << "      "
     << (K.Variable == TimeStepTarget ? rt::SetReducedTimeStep + "("
                                      : rt::SetVariable + "(" + stringLiteral(K.Variable) + ", ")
     << (Rows.empty() ? "backend.reduce(" : "backend.reduceOver(" + Rows) << "P.id, values, "
     << rt::ReduceOp << "::" << Op << "));\n"
     << "    }\n";
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

std::string searchGeometryText(const CodePlan &Plan, const Kernel &K) {
  if (!Plan.SmoothingSearch)
    return rt::FixedGeometry + "(run.radius())";
  return rt::SmoothingGeometry + "(run.support(), " + Plan.readColumn("smoothing_length") +
         ", P.id, backend.owned(), run.box(), " + std::to_string(Plan.Dim) + ", step, \"" +
         K.Function + "\", &Backend::combineMax" + (Plan.SymmetricSearch ? ", true" : "") + ")";
}

std::string smoothingLengthAccessor(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "";
  return ", [](std::uint32_t row) { return double(" + Plan.readColumn("smoothing_length") +
         "[row]); }";
}

std::string domainCellSizeText(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "[&] { return run.radius(); }";
  return "[&] {\n"
         "    return " +
         rt::SmoothingGeometry + "(run.support(), " + Plan.readColumn("smoothing_length") +
         ", P.id, backend.owned(), run.box(), " + std::to_string(Plan.Dim) +
         ", 0, \"(start)\").domainCellSize();\n"
         "  }";
}

std::string neighbourTableDeclaration(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "";
  return rt::NeighbourTable + "<" + std::to_string(Plan.Dim) +
         ", Stored> table; // the lists of the current search\n";
}

std::string neighbourTableBuild(const CodePlan &Plan) {
  if (!Plan.SmoothingSearch)
    return "";
  return "    table.build(backend.grid(), P.pos, P.id, " + Plan.readColumn("smoothing_length") +
         ", at, backend.owned());\n";
}

std::string neighbourListText(const CodePlan &Plan, const Kernel &K) {
  // A neighbour type filters the list as it is built (Neighbours).
  const std::string Filter = K.NeighbourType.empty()
                                 ? ""
                                 : ", P." + Plan.Member.at(TypeField) + ", " +
                                       std::to_string(Plan.typeIndex(K.NeighbourType)) + "u";
  if (!Plan.SmoothingSearch)
    return "NeighbourList(backend.grid(), P.pos, i" + Filter + ")";
  if (Filter.empty())
    return "table.list(i)";
  return "NeighbourList(table.list(i).begin(), table.list(i).end()" + Filter + ")";
}

void emitSnapshots(std::ostream &OS, const Kernel &K, const CodePlan &Plan) {
  for (const std::string &F : Plan.Snapshotted) {
    if (!K.NeighbourReads.count(F))
      continue; // the kernel never reads it through a neighbour
    const std::string &Col = Plan.Member.at(F);
    if (K.Hazards.count(F))
      OS << "    " << Col << "_snapshot = P." << Col
         << "; // written here, read through neighbours\n"
         << "    " << Col << "_neighbour = " << Col << "_snapshot.data();\n";
    else
      OS << "    " << Col << "_neighbour = P." << Col << ".data();\n";
  }
}

void emitHoistedColumns(std::ostream &OS, const CodePlan &Plan, unsigned K) {
  for (unsigned I = 0; I < Plan.Hoisted.size(); ++I) {
    const HoistedExpr &H = *Plan.Hoisted[I];
    if (std::find(H.Kernels.begin(), H.Kernels.end(), K) == H.Kernels.end())
      continue;
    const std::string Column = CodePlan::hoistColumn(I);
    OS << "    // " << H.Written << " (" << H.Function << "), once per row, not per pair.\n"
       << "    " << Column << ".resize(P.size());\n"
       << "    for (std::size_t row = 0; row < P.size(); ++row)\n"
       << "      " << Column << "[row] = " << Plan.hoistComputeText(I, "row") << ";\n";
  }
}

} // namespace wash::tr
