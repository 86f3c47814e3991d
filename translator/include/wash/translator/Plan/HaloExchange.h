//===- HaloExchange.h - what MPI must send before a force kernel -*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

namespace wash::tr {

/// For each force kernel, the fields that must be current on halo particles
/// (copies of another rank's particles) before it runs: pos, to find them as
/// neighbours, and every field the kernel reads through neighbours. Fills
/// Kernel::HaloFields, and Kernel::HaloSends: what is actually exchanged before
/// the kernel. The first kernel of a neighbour search rebuilds the halo and
/// sends all its HaloFields; a later kernel of the same search sends only the
/// fields it needs that some kernel wrote since they were last sent.
/// Needs summariseAccesses and planNeighbourSearch.
void planHalos(Model &M);

} // namespace wash::tr
