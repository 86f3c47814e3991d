//===- EmitMpi.h - the MPI program's driver ---------------------*- C++ -*-===//
//
// The MPI program shares the storage header and the rewritten user code with
// the shared-memory programs; its driver distributes the particles, rebuilds
// the halo for each neighbour search and, before each later force kernel,
// sends exactly the fields the halo plan lists (Kernel::HaloSends).
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Emit/CodePlan.h"
#include "wash/translator/Model.h"

#include <string>
#include <vector>

namespace wash::tr {

std::string emitMpiDriver(const Model &M, const CodePlan &Plan,
                          const std::vector<std::string> &Callees);

} // namespace wash::tr
