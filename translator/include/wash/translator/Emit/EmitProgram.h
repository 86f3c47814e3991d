//===- EmitProgram.h - the generated project, assembled ---------*- C++ -*-===//
#pragma once

#include "wash/translator/Emit/WriteProject.h"
#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/Includes.h"
#include "wash/translator/Model.h"
#include "wash/translator/Options.h"

#include "clang/AST/ASTContext.h"

#include <vector>

namespace wash::tr {

/// Plans storage, rewrites the user's source (and the user headers Includes
/// reach, each into the project under user/) and emits the storage header, the
/// driver and CMakeLists.txt for Opts.Target into Files (nothing is written to
/// disk here). Returns false after an error.
bool emitProgram(clang::ASTContext &Ctx, Diagnoser &D, const Model &M, const AstRefs &Refs,
                 const IncludeDirectives &Includes, const Options &Opts,
                 std::vector<GeneratedFile> &Files);

/// Where a generated CMakeLists.txt looks for wash: next to the installed
/// translator at ExecutablePath first, then the build tree this translator
/// was built in.
std::vector<std::string> packageHints(const std::string &ExecutablePath);

} // namespace wash::tr
