//===- CompileGate.h - the generated code must compile ----------*- C++ -*-===//
//
// Before the project is written, clang parses and type-checks the generated
// program (with its header and the rewritten user headers) in memory, as the
// generated project's build would: a translator bug then becomes a wash
// error at the user's line instead of compiler errors in generated files.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Backends.h"
#include "wash/translator/Diagnostics.h"
#include "wash/translator/Emit/WriteProject.h"
#include "wash/translator/Model.h"

#include <string>
#include <vector>

namespace wash::tr {

/// One error clang found in the generated code.
struct CompileError {
  /// Where clang places it after the #line directives: the user's file
  /// for rewritten user code, else a generated file (Pos.File may then be
  /// relative, or empty for an error with no location).
  SourcePos Pos;
  /// The generated file (its name in the project) and physical line the
  /// error is on; Line is 0 when the error is outside the project's files.
  std::string GeneratedFile;
  unsigned GeneratedLine = 0;
  std::string Message; ///< clang's message.
  /// For an error in the driver: the registration of the kernel whose
  /// section of the driver it is in, if any (the user's place to report it).
  SourcePos Kernel;
};

/// What the gate compiles with.
struct CompileGateSetup {
  std::string ProjectDir; ///< Where the project will be written.
  std::string Program;    ///< The program's name in the project.
  Backend Target = Backend::Serial;
  std::string ExecutablePath;        ///< To find an installed wash's headers.
  std::vector<std::string> UserArgs; ///< The user's flags after `--`.
};

/// Runs clang -fsyntax-only on Setup.Program among Files (an in-memory
/// overlay at Setup.ProjectDir over the real file system) as the generated
/// project builds it: -std=c++20, the backend's include folders (and -fopenmp
/// where its target uses OpenMP), the project folder, then the user's flags.
/// Returns every error clang reports (warnings are not errors), in order;
/// those in the driver name the registration of the kernel (of Kernels)
/// whose section they are in.
std::vector<CompileError> checkGeneratedCode(const std::vector<GeneratedFile> &Files,
                                             const CompileGateSetup &Setup,
                                             const std::vector<Kernel> &Kernels);

/// The include folders of the backend's headers: <prefix>/include next to
/// an installed wash, else the source tree's runtime/ and backends/ folders;
/// then what the backend's own dependencies (MPI) need.
std::vector<std::string> backendIncludeDirs(const std::string &ExecutablePath, Backend Target);

} // namespace wash::tr
