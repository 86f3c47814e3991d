//===- InferAccesses.h - what each kernel reads and writes ------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

#include <optional>
#include <vector>

namespace wash::tr {

/// Kernel::Accesses of each of Kernels: each property getter and setter
/// reached from the kernel's body, attributed to the kernel's own particle or
/// to a neighbour. Values of particle type carry a role (own particle,
/// neighbour, neighbour list, iterator into it) through locals, copies,
/// references, pointers, casts, range-for, indexing, lambdas (called directly
/// or handed to a standard algorithm), and into helpers, whose parameters take
/// the roles of their arguments. Reports neighbour writes, recursion, calls
/// through function pointers and undefined helpers that receive a particle,
/// and accessors called on particles of unknown origin, and state outside the
/// particle that a per-particle kernel may change (GlobalWrites). nullopt on
/// error.
std::optional<std::vector<std::vector<Access>>>
inferAccesses(ProgramIndex &Index, Diagnoser &D, const AstRefs &Refs,
              const std::vector<Kernel> &Kernels, const std::vector<ParticleType> &Types);

} // namespace wash::tr
