//===- HaloExchange.h - what MPI must send before a force kernel -*- C++ -*-===//
#pragma once

#include "wash/translator/Model.h"

#include <vector>

namespace wash::tr {

/// Kernel::HaloFields, HaloSends, HaloNewRowSends and HaloCurrent of one kernel.
struct KernelHalo {
  FieldSet Fields, Sends, NewRowSends, Current;
};

/// For each force kernel, the fields that must be current on halo particles
/// (copies of another rank's particles) before it runs: pos, to find them as
/// neighbours, and every field the kernel reads through neighbours
/// (KernelHalo::Fields), and what is exchanged before the kernel.
///
/// The first kernel of a neighbour search rebuilds the halo. A row a rank
/// received from the same rank at the previous build (the same particle) is
/// kept: it receives id, pos and the fields it needs that some kernel wrote
/// since they were last sent (Sends); the rest come from its previous copy.
/// Every other row (a particle that moved into the halo, migrated, or the
/// first build) is new: it receives the fields it needs and those current on
/// kept rows that a force kernel reads through neighbours before any kernel
/// writes them (NewRowSends), so that afterwards every halo row holds the
/// same current fields. A later
/// kernel of the same search sends only the fields it needs that some kernel
/// wrote since they were last sent (Sends). Current: the fields it needs that
/// are not sent (current on the rows that need no send).
///
/// Current fields are found by walking the iterations until they repeat: the
/// fields current on every halo row at the start of an iteration are those
/// at its end (init kernels run before any halo). One per kernel, in order
/// (empty but for force kernels). Reads the kernels' Kind, NeighbourReads and
/// OwnWrites (summariseAccesses) and SearchGroup, an index into Searches
/// (planNeighbourSearch).
std::vector<KernelHalo> planHalos(const std::vector<Kernel> &Kernels,
                                  const std::vector<SearchGroup> &Searches);

} // namespace wash::tr
