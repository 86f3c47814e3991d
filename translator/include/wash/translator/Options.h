//===- Options.h - what the command line asked for --------------*- C++ -*-===//
#pragma once

#include "wash/translator/Backends.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace wash::tr {

/// The passes of the recipe, in the order it runs them (Passes.def).
enum class PassId {
#define WASH_PASS(Id, Name) Id,
#include "wash/translator/Passes.def"
};
/// The pass's --dump-after name: its entry function's name in kebab case.
const char *passName(PassId P);
/// The pass named Name, if there is one.
std::optional<PassId> findPass(std::string_view Name);
/// Every pass name in pipeline order, separated by Separator.
std::string passNames(std::string_view Separator);

struct Options {
  std::string Source;                    ///< The simulation file.
  std::vector<std::string> CompilerArgs; ///< After `--`.
  Backend Target = Backend::Serial;
  std::string OutputDir = ".";
  /// --depfile: where to write a Makefile-syntax list of every file the
  /// translation read, for the build to re-translate when one changes.
  std::string DepFile;
  bool DumpModel = false;
  /// --dump-after: print the model right after this pass and stop (wins
  /// over DumpModel, which prints it after the last pass).
  std::optional<PassId> DumpAfter;
  std::string ExecutablePath; ///< To find an installed wash's API headers.
  /// Type-check the generated code before writing it (--no-compile-gate
  /// turns it off, for debugging the translator).
  bool CompileGate = true;
  /// --force: overwrite generated files that changed since wash wrote them,
  /// or that wash did not write (never an input of the translation).
  bool Force = false;
};

} // namespace wash::tr
