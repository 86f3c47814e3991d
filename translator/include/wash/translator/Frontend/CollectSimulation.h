//===- CollectSimulation.h - settings, forces and kernels -------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/AstRefs.h"
#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ProgramIndex.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"

#include <optional>

namespace wash::tr {

/// What main sets and registers: the parts of the model it fills.
struct Registrations {
  Settings Sim;
  std::vector<ForceRegistration> Forces;
  std::vector<ParticleType> Types;
  std::vector<Kernel> Kernels;
};

/// Walks main, and the functions it calls, in the order C++ runs them (each
/// call as if inlined, its parameters bound to the call's arguments) and
/// returns the settings, the forces and the kernels it registers (kernels
/// checked by resolveKernel; Refs gets main and their definitions), for a
/// simulation of Dimension (detectDimension's). Then rejects every
/// registration call in user code the walk did not reach, or reached inside
/// a loop, and every use of a registration function other than a call.
/// nullopt on error.
std::optional<Registrations> collectSimulation(ProgramIndex &Index, Diagnoser &D,
                                               unsigned Dimension, AstRefs &Refs);

} // namespace wash::tr
