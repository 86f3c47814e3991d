//===- Includes.h - the include directives the parse saw --------*- C++ -*-===//
//
// Recorded by parseSimulation as the preprocessor reads them, so that the
// rewrite can redirect each one to the generated copy of the file it names
// (a directive skipped by a header guard or #pragma once leaves no trace in
// the AST or the source manager) and the depfile can list every input.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/InputFile.h"

#include "clang/Basic/SourceLocation.h"
#include "clang/Basic/SourceManager.h"

#include <string>
#include <vector>

namespace wash::tr {

struct IncludeDirective {
  clang::SourceLocation Hash;       ///< The directive's `#`.
  clang::CharSourceRange FileName;  ///< `<a/b.hpp>` or `"a/b.hpp"` as written.
  clang::OptionalFileEntryRef File; ///< What it resolved to.
  bool SystemFile = false;          ///< File is a system header.
};

/// A macro the user's files define (not a system header or the command line).
struct UserMacro {
  std::string Name;
  clang::SourceLocation Loc; ///< Its first definition.
};

/// What the preprocessor read: the include directives, in order, and the
/// macros user files define (generated code must not meet them).
struct IncludeDirectives : std::vector<IncludeDirective> {
  std::vector<UserMacro> Macros;
};

/// Every file the translation read: Source, then each included file once,
/// in the order first included (absolute paths).
std::vector<std::string> inputFiles(const std::string &Source, const IncludeDirectives &Includes);

/// inputFiles, each with its content's hash: what `wash run` keys its cache
/// on. Hashed from the source manager, so that an edit made while the
/// translation runs is not taken for what it translated.
std::vector<InputFile> hashedInputFiles(clang::SourceManager &SM, const std::string &Source,
                                        const IncludeDirectives &Includes);

} // namespace wash::tr
