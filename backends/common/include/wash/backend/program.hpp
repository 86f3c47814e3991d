//===- wash/backend/program.hpp - what generated code includes ----*- C++ -*-===//
//
// Generated programs include this instead of <wash/wash.hpp>: the API's
// vectors, constants, settings and random numbers, plus the pieces the generated driver uses.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/cell_grid.hpp>
#include <wash/backend/checkpoint.hpp>
#include <wash/backend/columns.hpp>
#include <wash/backend/frame_builder.hpp>
#include <wash/backend/neighbour_table.hpp>
#include <wash/backend/neighbours.hpp>
#include <wash/backend/particle_types.hpp>
#include <wash/backend/periodic.hpp>
#include <wash/backend/reduce.hpp>
#include <wash/backend/run.hpp>
#include <wash/backend/search_geometry.hpp>
#include <wash/backend/variables.hpp>
#include <wash/math.hpp>
#include <wash/random.hpp>
#include <wash/settings.hpp>
#include <wash/vec.hpp>

#include <wash/call_site.hpp>

namespace wash {
/// Ends the run after this iteration (wash.hpp). The translator allows it
/// only in void kernels, which every MPI rank runs alike.
void stop(CallSite loc = CallSite::current());
} // namespace wash
