//===- HaloExchange.h - what MPI must send before a force kernel -*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// For each force kernel, the fields that must be current on halo particles
/// (copies of another rank's particles) before it runs: pos, to find them as
/// neighbours, and every field the kernel reads through neighbours. Fills
/// Kernel::HaloFields. Needs summariseAccesses.
void planHalos(Model &M);

} // namespace wash::tr
