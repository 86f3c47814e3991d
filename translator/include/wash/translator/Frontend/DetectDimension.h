//===- DetectDimension.h - 2D or 3D -----------------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Frontend/Diagnoser.h"
#include "wash/translator/Model.h"

#include "clang/AST/ASTContext.h"
#include "llvm/ADT/StringRef.h"

#include <optional>

namespace wash::tr {

/// Before parsing: the dimension the source's vector types suggest (the
/// first of Vec2D, Vec3D or Vec<..., N> among its tokens, comments skipped),
/// or 2. The header needs WASH_DIM to match, so the driver defines it.
unsigned guessDimension(llvm::StringRef Source);

/// After parsing: the dimension (Model::Sim.Dimension) the vector types the
/// user's code spells say (ParsedDim, the WASH_DIM it was parsed with, if it
/// spells none). Mixing 2D and 3D vectors is an error: nullopt.
std::optional<unsigned> detectDimension(clang::ASTContext &Ctx, Diagnoser &D, unsigned ParsedDim);

} // namespace wash::tr
