//===- NeighbourDistances.h - whether searches keep distances ---*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// The distance uses findNeighbourDistances found (Found) that can read the
/// search's distance, which is then bit for bit the user's: all of them for
/// double positions (the search computes in double, a float Vec's magnitude
/// in float), the one-radius search (the smoothing-length rule reorders its
/// lists), and no force kernel writing its particle's position (the search
/// saw the old one); otherwise none. The search keeps distances if any
/// remain. Reads Sim's Precision and SmoothingLengthSupport and the kernels'
/// Kind and OwnWrites (summariseAccesses).
std::vector<DistanceUse> planNeighbourDistances(const std::vector<DistanceUse> &Found,
                                                const Settings &Sim,
                                                const std::vector<Kernel> &Kernels);

} // namespace wash::tr
