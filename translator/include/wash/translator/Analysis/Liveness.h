//===- Liveness.h - which fields need storage -------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Field::Live and OutputOnly of one field.
struct FieldLiveness {
  bool Live = false;
  bool OutputOnly = false;
};

struct Liveness {
  std::vector<FieldLiveness> Fields; ///< One per field, in order.
  std::vector<Finding> Findings;     ///< ForceUnused.
};

/// Marks each field (from resolveFields) live or dead and output-only, from
/// the kernels' OwnReads, OwnWrites and NeighbourReads (summariseAccesses).
/// Output holds every property and force, so a field is live if some kernel
/// reads or writes it, or if it is one of the columns output always has. A
/// field nothing touches is dead and gets no storage (ForceUnused warns about
/// registered ones); a live field no kernel reads is output-only.
Liveness computeLiveness(const std::vector<Field> &Fields, const std::vector<Kernel> &Kernels);

} // namespace wash::tr
