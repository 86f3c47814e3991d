//===- NeighbourDistances.h - whether searches keep distances ---*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// Keeps the distance uses findNeighbourDistances found only where the
/// search's distance is bit for bit the user's: double positions (the search
/// computes in double, a float Vec's magnitude in float), the one-radius
/// search (the smoothing-length rule reorders its lists), and no force kernel
/// writing its particle's position (the search saw the old one): the search
/// keeps distances if any remain. Needs summariseAccesses.
void planNeighbourDistances(Model &M);

} // namespace wash::tr
