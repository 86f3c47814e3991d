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
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Kernel::AlwaysWrites of each of Kernels (empty but for update and force
/// kernels); Refs.Kernels are their definitions.
std::vector<FieldSet> findAlwaysWrites(ProgramIndex &Index, const AstRefs &Refs,
                                       const std::vector<Kernel> &Kernels);

} // namespace wash::tr
