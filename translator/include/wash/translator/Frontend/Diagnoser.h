//===- Diagnoser.h - wash diagnostics through clang -------------*- C++ -*-===//
//
// Registers every DiagnosticKinds.def entry as a clang custom diagnostic and
// reports them, and the model passes' Findings, through the compiler's
// DiagnosticsEngine: the output is clang's file:line:col format with carets.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Diagnostics.h"

#include "clang/Basic/Diagnostic.h"
#include "clang/Basic/SourceManager.h"
#include "llvm/ADT/ArrayRef.h"

#include <set>
#include <utility>

namespace wash::tr {

class Diagnoser {
public:
  Diagnoser(clang::DiagnosticsEngine &Engine, clang::SourceManager &SM);

  /// Reports Id at Loc with its %0, %1... arguments. A diagnostic already
  /// reported at the same place is dropped: a helper reached from several
  /// kernels or call sites is analysed more than once.
  void report(DiagId Id, clang::SourceLocation Loc, llvm::ArrayRef<std::string> Args = {});
  void report(const Finding &F);

  SourcePos toPos(clang::SourceLocation Loc) const;
  clang::SourceLocation fromPos(const SourcePos &P) const;

  bool hasErrors() const { return Errors > 0; }
  clang::SourceManager &sourceManager() const { return SM; }

private:
  clang::DiagnosticsEngine &Engine;
  clang::SourceManager &SM;
  std::vector<unsigned> Ids;
  std::set<std::pair<unsigned, DiagId>> Seen;
  unsigned Errors = 0;
  bool LastDropped = false; // Notes follow their diagnostic's fate.
};

} // namespace wash::tr
