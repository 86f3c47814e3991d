//===- ResolveFields.h - the fields a simulation stores ---------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

struct ResolvedFields {
  std::vector<Field> Fields;     ///< Model::Fields, liveness not yet computed.
  std::vector<Finding> Findings; ///< ForceCreated and ForceKindMismatch.
};

/// The fields the simulation stores: the built-in properties, the registered
/// forces (Forces) in registration order, then forces that kernels use
/// without registering them, in order of first use in the kernels' raw
/// Accesses (init kernels first, as the runtime creates them). Vectors have
/// Dim components. Reports ForceCreated for each of those at its first
/// use and ForceKindMismatch where a scalar accessor meets a vector force or
/// the reverse. A typed simulation (Typed: it adds particle types) has the
/// builtin field "type" after the others.
ResolvedFields resolveFields(unsigned Dim, const std::vector<ForceRegistration> &Forces,
                             const std::vector<Kernel> &Kernels, bool Typed = false);

} // namespace wash::tr
