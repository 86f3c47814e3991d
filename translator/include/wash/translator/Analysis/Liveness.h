//===- Liveness.h - which fields need storage -------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// Marks each field live or dead and output-only. Output holds every property
/// and force, so a field is live if some kernel reads or writes it, or if it is
/// one of the columns output always has. A field nothing touches is dead and
/// gets no storage (ForceUnused warns about registered ones); a live field no
/// kernel reads is output-only. Needs summariseAccesses and resolveFields.
void computeLiveness(Model &M);

} // namespace wash::tr
