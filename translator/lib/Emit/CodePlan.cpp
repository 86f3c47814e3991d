//===- CodePlan.cpp - storage, names and access text for generated code ---===//
#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Emit/RuntimeNames.h"
#include "wash/translator/WashApiTable.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace wash::tr {
namespace {

bool isIdentifier(const std::string &S) {
  if (S.empty() || !(std::isalpha((unsigned char)S[0]) || S[0] == '_'))
    return false;
  return std::all_of(S.begin(), S.end(),
                     [](char C) { return std::isalnum((unsigned char)C) || C == '_'; });
}

/// A member name for force `Name`: the name itself when it is a plain
/// identifier nothing else uses, else a mangled one.
std::string memberFor(const std::string &Name, unsigned Index, const std::set<std::string> &Taken) {
  static const std::set<std::string> Reserved = {
      // C++ keywords a force might be called, and the generated struct's own names.
      "auto",   "bool",   "break",    "case",     "char",    "class",    "const",        "default",
      "delete", "do",     "double",   "else",     "enum",    "float",    "for",          "if",
      "int",    "long",   "new",      "operator", "private", "public",   "return",       "short",
      "signed", "sizeof", "static",   "struct",   "switch",  "template", "this",         "throw",
      "try",    "union",  "unsigned", "void",     "while",   "size",     "forEachColumn"};
  // Names starting with two underscores or one and a capital are the
  // implementation's (its macros among them).
  bool ImplementationName = Name.rfind("__", 0) == 0 || (Name.size() > 1 && Name[0] == '_' &&
                                                         std::isupper((unsigned char)Name[1]));
  if (isIdentifier(Name) && !Taken.count(Name) && !Reserved.count(Name) && !ImplementationName &&
      Name.rfind("force_", 0) != 0)
    return Name;
  std::string Mangled = "force_" + std::to_string(Index) + "_";
  for (char C : Name)
    Mangled += std::isalnum((unsigned char)C) ? C : '_';
  return Mangled;
}

} // namespace

std::string CodePlan::variableSlot(const std::string &Name) {
  bool Plain = !Name.empty() && std::all_of(Name.begin(), Name.end(), [](char C) {
    return std::isalnum((unsigned char)C) || C == '_';
  });
  if (Plain)
    return "var_" + Name;
  // Any other name, byte by byte in hex: no `var_`, so no clash with the above.
  std::string Slot = "var";
  for (char C : Name) {
    const char *Hex = "0123456789abcdef";
    Slot += Hex[(unsigned char)C >> 4];
    Slot += Hex[(unsigned char)C & 15];
  }
  return Slot;
}

std::string CodePlan::sourceName() const { return Stem + "." + backendName(Target) + ".cpp"; }

unsigned CodePlan::typeIndex(const std::string &Name) const {
  return unsigned(std::find(Types.begin(), Types.end(), Name) - Types.begin());
}

std::string CodePlan::isTypeText(const std::string &Object, const std::string &Type) const {
  return "(wash_gen::P." + Member.at(TypeField) + "[" + Object +
         "] == " + std::to_string(typeIndex(Type)) + "u)";
}

std::string CodePlan::setTypeText(const std::string &Object, const std::string &Type) const {
  return "wash_gen::P." + Member.at(TypeField) + "[" + Object +
         "] = " + std::to_string(typeIndex(Type)) + "u";
}

std::string CodePlan::storedType(const Field &F) const {
  if (F.Name == "id")
    return "std::uint64_t";
  if (F.Origin == FieldOrigin::Builtin && F.Name == TypeField)
    return "std::uint32_t";
  return F.Kind == ForceKind::Vector ? "wash_gen::Stored" : "wash_gen::Real";
}

std::string CodePlan::apiType(const Field &F) const {
  if (F.Name == "id")
    return "std::size_t";
  return F.Kind == ForceKind::Vector ? "wash::ParticleVec" : "double";
}

std::string CodePlan::readText(const std::string &Name, const std::string &Object,
                               ForceKind Kind) const {
  auto Known = ByName.find(Name);
  if (Known == ByName.end()) // Only in code no kernel runs: no field, no storage.
    return Kind == ForceKind::Vector ? "wash::ParticleVec()" : "double()";
  const Field &F = *Known->second;
  if (!F.Live) // Never written: it reads as zero.
    return apiType(F) + "()";
  if (Snapshotted.count(Name))
    return "wash_gen::get_" + Member.at(Name) + "(" + Object + ")";
  std::string Access = "wash_gen::P." + Member.at(Name) + "[" + Object + "]";
  if (F.Name == "id")
    return "std::size_t(" + Access + ")";
  return Float ? apiType(F) + "(" + Access + ")" : Access;
}

std::string CodePlan::writeText(const std::string &Name, const std::string &Object,
                                const std::string &Value) const {
  auto It = Member.find(Name);
  // Dead (acc, never read nor output) or only in code no kernel runs: keep
  // the value's side effects.
  if (It == Member.end())
    return "(void)(" + Value + ")";
  std::string Target = "wash_gen::P." + It->second + "[" + Object + "]";
  if (!Float)
    return Target + " = " + Value;
  // rounded(): what g++ stores is what a later read sees (columns.hpp).
  if (ByName.at(Name)->Kind == ForceKind::Vector)
    return Target + " = " + rt::Rounded + "(wash_gen::Stored(wash::ParticleVec(" + Value + ")))";
  return Target + " = " + rt::Rounded + "(wash_gen::Real(" + Value + "))";
}

std::optional<std::string> CodePlan::distanceText(const SourcePos &P,
                                                  const std::string &Written) const {
  auto It = DistanceAt.find({P.File, P.Line, P.Col});
  if (It == DistanceAt.end())
    return std::nullopt;
  const DistanceUse &U = *It->second;
  std::string Read = U.List + ".distance(" + U.Neighbour + ")";
  if (U.SelfAlways)
    return Read;
  // A generic helper: the own particle in some calls, a neighbour in others.
  return "(wash_gen::isSelf<decltype(" + U.Self + ")> ? " + Read + " : " + Written + ")";
}

std::optional<std::string> CodePlan::hoistedText(const SourcePos &Begin,
                                                 const SourcePos &End) const {
  auto It = HoistAt.find({Begin.File, Begin.Line, Begin.Col, End.Line, End.Col});
  if (It == HoistAt.end())
    return std::nullopt;
  return "double(wash_gen::" + hoistColumn(It->second) + "[" + Hoisted[It->second]->Neighbour +
         "])";
}

std::string CodePlan::hoistComputeText(unsigned I, const std::string &Row) const {
  std::string Text;
  for (const HoistPiece &Piece : Hoisted.at(I)->Compute)
    Text += Piece.isRead() ? readText(Piece.Field, Row, Piece.Kind) : Piece.Text;
  return Text;
}

CodePlan planCode(const Model &M, Backend Target, const std::string &Stem) {
  CodePlan Plan;
  Plan.Target = Target;
  Plan.Stem = Stem;
  Plan.Dim = M.Sim.Dimension;
  Plan.Float = M.Sim.Precision == "float";
  Plan.SmoothingSearch = M.searchesBySmoothingLength();
  Plan.SymmetricSearch = Plan.SmoothingSearch && M.Sim.SymmetricSupport;

  std::set<std::string> Taken;
  for (const std::string &B : builtinFieldNames())
    Taken.insert(B);
  unsigned Index = 0;
  for (const Field &F : M.Fields) {
    ++Index;
    Plan.ByName[F.Name] = &F;
    if (!F.Live)
      continue;
    Plan.Stored.push_back(&F);
    std::string Member =
        F.Origin == FieldOrigin::Builtin ? F.Name : memberFor(F.Name, Index, Taken);
    Taken.insert(Member);
    Plan.Member[F.Name] = Member;
  }

  // Output: builtins (not acc), registered forces in order, created ones by name.
  for (const BuiltinField &B : builtinFields())
    if (B.AlwaysOutput && B.Kind != FieldKind::Id) // ids are the frame's own column
      if (const Field *F = M.findField(B.Name))
        Plan.Output.push_back(F);
  for (const ForceRegistration &R : M.Forces)
    if (const Field *F = M.findField(R.Name))
      Plan.Output.push_back(F);
  std::vector<const Field *> Created;
  for (const Field &F : M.Fields)
    if (F.Origin == FieldOrigin::Created)
      Created.push_back(&F);
  std::sort(Created.begin(), Created.end(),
            [](const Field *A, const Field *B) { return A->Name < B->Name; });
  Plan.Output.insert(Plan.Output.end(), Created.begin(), Created.end());
  // A typed simulation's type column comes last (docs/semantics.md).
  for (const ParticleType &T : M.Types)
    Plan.Types.push_back(T.Name);
  if (M.typed())
    if (const Field *F = M.findField(TypeField); F && F->Origin == FieldOrigin::Builtin)
      Plan.Output.push_back(F);
  for (const Kernel &K : M.Kernels)
    Plan.RestrictsKernels |= !K.ParticleType.empty();

  for (const Kernel &K : M.Kernels)
    Plan.Snapshotted.insert(K.Hazards.begin(), K.Hazards.end());

  // A distributed backend's migration and sort move every column.
  if (!backendInfo(Target).Distributed)
    Plan.RewrittenAfterSearch = M.RewrittenAfterSearch;
  for (const HoistedExpr &H : M.Hoisted) {
    Plan.HoistAt[{H.Begin.File, H.Begin.Line, H.Begin.Col, H.End.Line, H.End.Col}] =
        unsigned(Plan.Hoisted.size());
    Plan.Hoisted.push_back(&H);
  }
  for (const DistanceUse &U : M.Distances)
    Plan.DistanceAt[{U.Call.File, U.Call.Line, U.Call.Col}] = &U;
  return Plan;
}

} // namespace wash::tr
