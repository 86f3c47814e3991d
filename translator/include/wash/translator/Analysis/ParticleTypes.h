//===- ParticleTypes.h - which particle types use each field ----*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace wash::tr {

/// The particle types (indices into Model::Types) whose particles' values of
/// a field kernels read or write.
struct FieldTypeUse {
  std::set<unsigned> ReadFor, WrittenFor;
};

/// Per field name, from each kernel's OwnReads, OwnWrites and NeighbourReads
/// (summariseAccesses): a kernel registered for a type reads and writes its
/// own particle for that type only, and reads neighbours for its neighbour
/// type; a kernel without one counts for every type, and so do init kernels
/// (they create particles of any type). A field missing from ReadFor for a
/// type is never read by any kernel for particles of that type.
std::map<std::string, FieldTypeUse> fieldTypeUses(const std::vector<ParticleType> &Types,
                                                  const std::vector<Kernel> &Kernels);

} // namespace wash::tr
