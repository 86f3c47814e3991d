//===- TypeName.h - evaluating and checking a particle type name -*- C++ -*-===//
//
// A particle type name (add_particle_type, a kernel registration's type
// arguments, is_type and set_type) must be known at translation: the
// generated code compares and stores the type's index.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Frontend/ParameterBindings.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Expr.h"

#include <optional>
#include <string>
#include <vector>

namespace wash::tr {

/// The name NameArg evaluates to, an identifier; reports
/// ParticleTypeNotConstant or ParticleTypeInvalid and returns nullopt otherwise.
std::optional<std::string> particleTypeName(const clang::Expr *NameArg, clang::ASTContext &Ctx,
                                            Diagnoser &D, const CallContext *Context = nullptr);

/// As particleTypeName, and one of Types (ParticleTypeUnknown otherwise).
std::optional<std::string> knownParticleType(const clang::Expr *NameArg, clang::ASTContext &Ctx,
                                             Diagnoser &D, const std::vector<ParticleType> &Types,
                                             const CallContext *Context = nullptr);

} // namespace wash::tr
