//===- CheckVariables.h - every variable used is added ----------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"

#include "clang/AST/ASTContext.h"

namespace wash::tr {

/// Checks, in all user code, that every variable name get_variable,
/// set_variable and add_reduction_kernel use is one some add_variable call
/// adds (the runtime would stop at the use): VariableUnknown, at the name,
/// with the closest added name as a suggestion. A name the translator cannot
/// evaluate is left to the run; one add_variable with such a name could add
/// anything, so then nothing is reported. Returns false on error.
bool checkVariables(clang::ASTContext &Ctx, Diagnoser &D);

} // namespace wash::tr
