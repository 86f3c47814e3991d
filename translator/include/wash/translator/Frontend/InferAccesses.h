//===- InferAccesses.h - what each kernel reads and writes ------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Fills Kernel::Accesses for every kernel: each property getter and setter
/// reached from the kernel's body, attributed to the kernel's own particle or
/// to a neighbour. Values of particle type carry a role (own particle,
/// neighbour, neighbour list, iterator into it) through locals, copies,
/// references, pointers, casts, range-for, indexing, lambdas (called directly
/// or handed to a standard algorithm), and into helpers, whose parameters take
/// the roles of their arguments. Reports neighbour writes, recursion, calls
/// through function pointers and undefined helpers that receive a particle,
/// and accessors called on particles of unknown origin. Returns false on error.
bool inferAccesses(clang::ASTContext &Ctx, Diagnoser &D, const AstRefs &Refs, Model &M);

} // namespace wash::tr
