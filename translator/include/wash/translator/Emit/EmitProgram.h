//===- EmitProgram.h - the generated project, assembled ---------*- C++ -*-===//
#pragma once

#include "wash/translator/Emit/WriteProject.h"
#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"
#include "wash/translator/Options.h"

#include "clang/AST/ASTContext.h"

#include <vector>

namespace wash::tr {

/// Plans storage, rewrites the user's source and emits the storage header, the
/// driver and CMakeLists.txt for Opts.Target into Files (nothing is written to
/// disk here). Returns false after an error.
bool emitProgram(clang::ASTContext &Ctx, Diagnoser &D, const Model &M, const AstRefs &Refs,
                 const Options &Opts, std::vector<GeneratedFile> &Files);

} // namespace wash::tr
