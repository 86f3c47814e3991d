//===- GlobalWrites.h - which global variable a statement writes -*- C++ -*-===//
//
// For the GlobalWriteInParticleKernel warning (InferAccesses): a per-particle
// kernel that writes a global or static variable gives results that depend on
// the order particles are visited in.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "clang/AST/Decl.h"
#include "clang/AST/Stmt.h"

namespace wash::tr {

/// The global or static variable S writes (an assignment, ++/--, a non-const
/// operator or member call), through members, subscripts, dereferences and
/// local references or pointers initialised to it; nullptr if none.
const clang::VarDecl *globalWrittenBy(const clang::Stmt *S);

} // namespace wash::tr
