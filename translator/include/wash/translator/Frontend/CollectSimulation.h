//===- CollectSimulation.h - settings, forces and kernels -------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Walks main, and the functions it calls, in source order and records the
/// settings, the forces and the kernels it registers (kernels checked by
/// resolveKernel). Then rejects every registration call in user code the walk
/// did not reach, or reached inside a loop, and every use of a registration
/// function other than a call. Needs detectDimension. Returns false on error.
bool collectSimulation(clang::ASTContext &Ctx, Diagnoser &D, Model &M, AstRefs &Refs);

} // namespace wash::tr
