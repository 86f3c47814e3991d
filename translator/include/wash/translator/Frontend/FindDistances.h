//===- FindDistances.h - neighbour distances the search already has -*- C++ -*-===//
//
// SPH kernels start every neighbour's terms with the distance r = |x_j - x_i|.
// The neighbour search computed its square to test the neighbour, so it can
// keep r (one vectorised square root per neighbour kept) and the kernel need
// not recompute it in every loop. This pass finds where a kernel or helper
// computes exactly that: `X.magnitude()` with X the difference of a
// neighbour's and the particle's positions, directly or through local
// variables never modified, the neighbour being an element of the neighbour
// list (a reference loop variable over it, `ns[k]`, or a reference to one).
// Anything else (copies of neighbours, lambdas, modified variables) is left
// as written.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Every such magnitude in the user's functions (Model::Distances).
std::vector<DistanceUse> findNeighbourDistances(clang::ASTContext &Ctx, const Diagnoser &D);

} // namespace wash::tr
