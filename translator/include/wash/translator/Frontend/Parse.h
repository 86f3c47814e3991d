//===- Parse.h - running clang on the simulation ----------------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/Includes.h"
#include "wash/translator/Options.h"

#include "clang/AST/ASTContext.h"

#include <functional>

namespace wash::tr {

/// Parses Opts.Source with clang and, if it compiles, calls OnAST with the AST
/// , a Diagnoser on the compiler's DiagnosticsEngine and the include
/// directives the preprocessor read. The command line is
/// `-std=c++20`, the resource directory and the wash API headers (as system
/// headers) baked in at build time, `-DWASH_DIM=<guessDimension>` unless the
/// user defines it, then the user's flags. Returns false if clang or OnAST
/// reported an error.
bool parseSimulation(const Options &Opts,
                     const std::function<void(clang::ASTContext &, Diagnoser &, unsigned Dim,
                                              const IncludeDirectives &)> &OnAST);

} // namespace wash::tr
