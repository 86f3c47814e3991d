//===- CodePlan.h - what the generated program stores and how it accesses it -*- C++ -*-===//
//
// The decisions every part of code generation shares: which fields get a
// column and under which C++ name, which need a snapshot, the output columns,
// and the text that replaces each particle access. Clang-free.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Model.h"
#include "wash/translator/Options.h"

#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace wash::tr {

struct CodePlan {
  Backend Target = Backend::Serial;
  std::string Stem; ///< The simulation file's name without extension.
  unsigned Dim = 2;
  bool Float = false;           ///< Storage precision.
  bool SmoothingSearch = false; ///< Neighbours within k * h_i (else one radius).
  bool SymmetricSearch = false; ///< ... within k * max(h_i, h_j).

  /// Every field by name, and the live ones in storage order (Model::Fields
  /// order) with their member names.
  std::map<std::string, const Field *> ByName;
  std::vector<const Field *> Stored;
  std::map<std::string, std::string> Member;
  /// Output columns in order (docs/semantics.md); dead ones are written as zeros.
  std::vector<const Field *> Output;
  /// Fields some force kernel writes on its particle and reads through
  /// neighbours: they get a snapshot column and a role-dependent accessor.
  FieldSet Snapshotted;
  /// The magnitudes that read the distances the neighbour lists keep, by
  /// (line, column) of the call; none if the lists keep no distances.
  std::map<std::tuple<std::string, unsigned, unsigned>, const DistanceUse *> DistanceAt;
  bool keepsDistances() const { return !DistanceAt.empty(); }
  /// Model::Hoisted: column `hoisted_<index>` each, found by the file and the
  /// positions of the expression's first and last tokens.
  std::vector<const HoistedExpr *> Hoisted;
  std::map<std::tuple<std::string, unsigned, unsigned, unsigned, unsigned>, unsigned> HoistAt;
  /// The column read that replaces the hoisted expression from Begin to End, if any.
  std::optional<std::string> hoistedText(const SourcePos &Begin, const SourcePos &End) const;
  /// What hoisted expression I computes for row Row (a variable of the driver).
  std::string hoistComputeText(unsigned I, const std::string &Row) const;
  static std::string hoistColumn(unsigned I) { return "hoisted_" + std::to_string(I); }
  /// Model::RewrittenAfterSearch: columns the search's sort leaves in the
  /// old order (none on a distributed backend, which moves every column).
  FieldSet RewrittenAfterSearch;
  bool reordersFewer() const {
    for (const Field *F : Stored)
      if (RewrittenAfterSearch.count(F->Name))
        return true;
    return false;
  }

  /// Particle types by index (none: untyped). Kernels restricted to a type
  /// loop over that type's rows, kept by the driver (see EmitDriver).
  std::vector<std::string> Types;
  /// The index of type Name (the translator checked that it exists).
  unsigned typeIndex(const std::string &Name) const;
  bool RestrictsKernels = false; ///< Some kernel runs for one type only.

  /// The names of the global variables whose `get_variable(name)` the rewrite
  /// lowered to a slot, in order of first use (filled by rewriteSource).
  std::vector<std::string> Variables;
  /// The slot generated code reads variable Name through (in wash_gen).
  static std::string variableSlot(const std::string &Name);

  std::string headerName() const { return Stem + ".wash.hpp"; }
  std::string sourceName() const;

  /// `P.<member>`: the column of a stored field.
  std::string readColumn(const std::string &Field) const { return "P." + Member.at(Field); }
  /// `P.<member>[Object]`, converted to the API type when storage is float.
  /// Kind is the accessor's: a force named only in code no kernel reaches
  /// (a helper never called) has no field and reads as a zero of that kind.
  std::string readText(const std::string &Field, const std::string &Object, ForceKind Kind) const;
  /// `P.<member>[Object] = Value`, converted to the storage type when float.
  std::string writeText(const std::string &Field, const std::string &Object,
                        const std::string &Value) const;
  /// `p.is_type("wall")`, `p.set_type("wall")`: a test or a store of the index.
  std::string isTypeText(const std::string &Object, const std::string &Type) const;
  std::string setTypeText(const std::string &Object, const std::string &Type) const;
  /// The distance to read for a magnitude call at P, if it reads one; Written
  /// is the call as rewritten, kept where the particle may be a neighbour.
  std::optional<std::string> distanceText(const SourcePos &P, const std::string &Written) const;
  /// The C++ type of a stored column element, and of a value in the API.
  std::string storedType(const Field &F) const;
  std::string apiType(const Field &F) const;
};

/// Decides storage, names and snapshots for M (which has been analysed).
CodePlan planCode(const Model &M, Backend Target, const std::string &Stem);

} // namespace wash::tr
