//===- FindAlwaysWrites.h - fields a kernel sets on every path --*- C++ -*-===//
//
// A kernel that sets a field of its particle on every path through it (a
// statement of the body's top level, or of a helper called there with the
// particle, before anything that may return) leaves no old value of it
// behind. Conditional writes, writes in loops and writes after a statement
// that may return do not count; a function with a goto counts nothing.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Fills Kernel::AlwaysWrites of every update and force kernel.
void findAlwaysWrites(clang::ASTContext &Ctx, const AstRefs &Refs, Model &M);

} // namespace wash::tr
