//===- Model.h - what the translator knows about a simulation ---*- C++ -*-===//
//
// Plain data, no Clang types: the frontend fills it in from the AST, the
// analysis and plan passes derive facts from it, and code generation will
// read it. Everything here is testable without parsing C++.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Diagnostics.h"

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace wash::tr {

/// A setting whose value may be a constant or known only at run time.
struct SettingValue {
  std::string Text; ///< The constant ("0.35", "\"double\"") or the source text.
  bool Constant = false;
  SourcePos Pos;
};

struct Settings {
  std::string Precision = "double"; ///< "double" (the default) or "float".
  unsigned Dimension = 2;
  std::optional<SettingValue> InfluenceRadius;
  /// set_smoothing_length_support: neighbours within k * h_i, so every force
  /// kernel's search reads its particle's smoothing length.
  std::optional<SettingValue> SmoothingLengthSupport;
  /// ... with wash::Support::Symmetric: j is i's neighbour within
  /// k * max(h_i, h_j), so every search reads the neighbours' h too.
  bool SymmetricSupport = false;
  std::optional<SettingValue> MaxIterations;
  /// Every value main may set, in source order (it may branch on argv).
  std::vector<SettingValue> SimulationNames;
  std::vector<SettingValue> OutputFileNames;
  bool CallsStart = false;

  bool searchesBySmoothingLength() const { return SmoothingLengthSupport.has_value(); }
};

enum class ForceKind { Scalar, Vector };
const char *forceKindName(ForceKind K);

/// A force registered with wash::add_force.
struct ForceRegistration {
  std::string Name;
  ForceKind Kind = ForceKind::Scalar;
  SourcePos Pos;
};

/// A particle type added with wash::add_particle_type; its index in
/// Model::Types is the value of its particles' "type" field.
struct ParticleType {
  std::string Name;
  SourcePos Pos;
};

enum class KernelKind { Init, Update, Force, Void, Reduction };
const char *kernelKindName(KernelKind K);

/// Which particle an access touches, relative to the kernel's own particle.
enum class Target { Own, Neighbour };
enum class Mode { Read, Write };

/// One property access found in a kernel (or a helper it calls). `Kind` is
/// set for forces: it says whether the scalar or the vector accessor was used.
struct Access {
  std::string Field;
  Target On = Target::Own;
  Mode How = Mode::Read;
  std::optional<ForceKind> Kind;
  SourcePos Pos;
  friend bool operator==(const Access &, const Access &) = default;
};

using FieldSet = std::set<std::string>;

struct Kernel {
  KernelKind Kind = KernelKind::Update;
  std::string Function;
  SourcePos Pos; ///< The registration call.
  /// Raw accesses in the order the frontend met them (registration order of
  /// kernels, then source order through calls): the first use of a force is
  /// the first element that names it.
  std::vector<Access> Accesses;

  // Reduction kernels: "sum", "min" or "max", and the variable it sets.
  std::string ReduceOp, Variable;
  /// The particle type it runs for (update, force and reduction kernels), and
  /// a force kernel's neighbours' type; "" for every type.
  std::string ParticleType, NeighbourType;

  // From summariseAccesses.
  FieldSet OwnReads, OwnWrites, NeighbourReads;
  // Filled by findAlwaysWrites (update and force kernels): own fields set on
  // every path through the kernel.
  FieldSet AlwaysWrites;
  // From findHazards: own writes also read through neighbours (a snapshot
  // each), and those that need none since the kernel's particles and its
  // neighbours are of different types.
  FieldSet Hazards, DisjointTypeWrites;
  // From planNeighbourSearch (force kernels only).
  int SearchGroup = -1;
  // From planHalos (force kernels only): fields halo particles need, those
  // that must be sent before this kernel (to the rows kept from the previous
  // search where this kernel rebuilds the halo), those a rebuild sends to
  // new rows, and the needed fields that are current and not sent.
  FieldSet HaloFields, HaloSends, HaloNewRowSends, HaloCurrent;
};

enum class FieldOrigin { Builtin, Registered, Created };

struct Field {
  std::string Name;
  FieldOrigin Origin = FieldOrigin::Builtin;
  ForceKind Kind = ForceKind::Scalar;
  unsigned Dim = 1;
  bool ReadOnly = false; ///< id: no setter.
  SourcePos Pos;         ///< Registration or first use.
  // From computeLiveness.
  bool Live = false;
  bool OutputOnly = false; ///< Written, never read: stored only for output.
};

/// A group of consecutive force kernels sharing one neighbour search.
struct SearchGroup {
  std::vector<unsigned> Kernels; ///< Indices into Model::Kernels.
};

/// `X.magnitude()` where X is the offset between a kernel's particle and one
/// of its neighbours, an element of the neighbour list (findNeighbourDistances):
/// the distance the search computed as it tested that neighbour.
struct DistanceUse {
  SourcePos Call;        ///< Where the magnitude call starts.
  std::string Function;  ///< The function it is in.
  std::string List;      ///< The neighbour list parameter's name.
  std::string Neighbour; ///< The neighbour as written: `n`, `ns[k]`.
  std::string Self;      ///< The particle parameter's name.
  /// The parameter is a `wash::Particle &`: always the kernel's own particle.
  /// Otherwise (a const reference or a copy, generic in the generated code)
  /// it may be a neighbour in some calls, and the generated code checks.
  bool SelfAlways = false;
};

/// A piece of the text that computes a hoisted expression for one row: C++
/// text, or a read of a neighbour's field (lowered by the emitter with the
/// row as the particle).
struct HoistPiece {
  std::string Text;
  std::string Field; ///< Set for a read.
  ForceKind Kind = ForceKind::Scalar;
  bool isRead() const { return !Field.empty(); }
  friend bool operator==(const HoistPiece &, const HoistPiece &) = default;
};

/// An expression inside a neighbour loop whose value depends only on one
/// neighbour's fields and on constants (findHoistable): computed once per
/// row into a column before the force kernels that reach it, and read from
/// there in the loop.
struct HoistedExpr {
  SourcePos Begin, End;  ///< The expression's first and last token.
  std::string Function;  ///< The function it is in.
  std::string Neighbour; ///< The loop variable it reads.
  std::string Written;   ///< The expression as written, for the dump.
  /// The same value for a row, in double: pieces in order.
  std::vector<HoistPiece> Compute;
  FieldSet Reads;                ///< The neighbour fields it reads.
  std::vector<unsigned> Kernels; ///< The force kernels whose calls reach it.
};

struct Model {
  std::string SourceFile;
  Settings Sim;
  std::vector<ForceRegistration> Forces;
  /// Particle types in the order they were added; none: an untyped simulation.
  std::vector<ParticleType> Types;
  std::vector<Kernel> Kernels;

  // Derived.
  std::vector<Field> Fields; ///< Builtins first, then forces; see resolveFields.
  std::vector<SearchGroup> Searches;
  std::vector<Finding> Findings; ///< Diagnostics from the model passes.
  /// Found by findNeighbourDistances; planNeighbourDistances keeps them only
  /// where the search's distances equal the user's.
  std::vector<DistanceUse> Distances;
  /// Fields every search is followed by a rewrite of, for every particle,
  /// before anything reads them (planSearchReorder): the search's reordering
  /// need not carry their old values.
  FieldSet RewrittenAfterSearch;
  /// Found by findHoistable; planHoists keeps those whose inputs no kernel
  /// that reaches them writes. Each is computed into column `hoisted_<index>`.
  std::vector<HoistedExpr> Hoisted;

  const Field *findField(const std::string &Name) const;
  bool typed() const { return !Types.empty(); }
  /// The index of type Name, or -1.
  int typeIndex(const std::string &Name) const;
  bool hasErrors() const;
  bool searchesBySmoothingLength() const { return Sim.searchesBySmoothingLength(); }
  /// Once planned: the neighbour search keeps distances for the uses left.
  bool searchKeepsDistances() const { return !Distances.empty(); }
};

/// The built-in particle properties in dump order (WashApiTable.h has the rest
/// of what the API says about them).
const std::vector<std::string> &builtinFieldNames();

} // namespace wash::tr
