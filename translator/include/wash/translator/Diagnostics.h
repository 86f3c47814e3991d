//===- Diagnostics.h - diagnostic kinds and findings ------------*- C++ -*-===//
//
// Clang-free: model passes report problems as Findings (plain data with a
// file:line:col); the Clang side turns them into DiagnosticsEngine reports so
// every diagnostic, from either side, looks like clang's own.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <string>
#include <vector>

namespace wash::tr {

enum class DiagId {
#define WASH_DIAG(Name, Level, Message) Name,
#include "wash/translator/DiagnosticKinds.def"
};

enum class DiagLevel { Error, Warning, Note };

DiagLevel diagLevel(DiagId Id);
const char *diagMessage(DiagId Id);

/// A point in the simulation source. Line 0 means "unknown".
struct SourcePos {
  std::string File;
  unsigned Line = 0;
  unsigned Col = 0;
  bool valid() const { return Line != 0; }
  friend bool operator==(const SourcePos &, const SourcePos &) = default;
};

/// One diagnostic found by a model pass, with its notes.
struct Finding {
  DiagId Id;
  SourcePos Pos;
  std::vector<std::string> Args;
  std::vector<Finding> Notes;
};

} // namespace wash::tr
