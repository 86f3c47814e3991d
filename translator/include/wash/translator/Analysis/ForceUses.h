//===- ForceUses.h - forces read but never written, and typos ---*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Forces (registered or created, from resolveFields) that no kernel writes
/// start at zero and stay there, whatever reads them: a read of one is an
/// error (ForceNeverWritten), with the registered or written force of the
/// closest name as a suggestion when one is close (a typo). A force written
/// but never read is only output; that is reported (ForceNeverRead) when a
/// read force has a close name, the likely intent. Reads and writes are the
/// kernels' OwnReads, OwnWrites and NeighbourReads (summariseAccesses); the
/// first access in registration order carries the diagnostic.
std::vector<Finding> checkForceUses(const std::vector<Field> &Fields,
                                    const std::vector<Kernel> &Kernels);

/// Every force is a column and a member of several generated structs: g++'s
/// time and memory on the generated code grow with the count (figures in
/// docs/diagnostics.md, ForceLimit). A ForceLimit error at the first use of
/// the force one past the limit, registered or accessed (Kernel::Accesses).
inline constexpr unsigned MaxForces = 1000;
std::vector<Finding> checkForceLimit(const std::vector<ForceRegistration> &Forces,
                                     const std::vector<Kernel> &Kernels);

} // namespace wash::tr
