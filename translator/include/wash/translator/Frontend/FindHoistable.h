//===- FindHoistable.h - per-neighbour work the pair loop repeats -*- C++ -*-===//
//
// Inside a neighbour loop, an expression that depends only on the
// neighbour's fields and on constants (an equation of state of its density,
// its sound speed) has the same value for every particle that has that
// neighbour: it can be computed once per particle before the kernel and read
// in the loop. This pass finds the largest such expressions in the range-for
// loops (by reference) over a neighbour-list parameter of a user function
// that only force kernels reach. Their operands may be scalar field reads of
// the loop variable, literals, const namespace-scope variables, parameters
// that every call binds to the same const global, local variables never
// modified initialised from these, and calls of pure functions (bodies it
// sees, with no side effects, no loops and no mutable state; <cmath>). It
// keeps those with a call or a division, of type double, outside macros and
// lambdas. See docs/backends.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Every such expression (Model::Hoisted), in source order; Kernels and
/// Refs.Kernels are collectSimulation's.
std::vector<HoistedExpr> findHoistable(const ProgramIndex &Index, const Diagnoser &D,
                                       const AstRefs &Refs, const std::vector<Kernel> &Kernels);

} // namespace wash::tr
