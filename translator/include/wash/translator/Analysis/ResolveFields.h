//===- ResolveFields.h - the fields a simulation stores ---------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// Builds Model::Fields: the built-in properties, the registered forces in
/// registration order, then forces that kernels use without registering them,
/// in order of first use (init kernels first, as the runtime creates them).
/// Reports ForceCreated for each of those at its first use and
/// ForceKindMismatch where a scalar accessor meets a vector force or the reverse.
void resolveFields(Model &M);

} // namespace wash::tr
