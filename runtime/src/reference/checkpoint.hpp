//===- checkpoint.hpp - checkpoint and restart of the reference runtime -*- C++ -*-===//
#pragma once

#include "state.hpp"

#include <wash/detail/run.hpp>

#include <cstdint>
#include <string>

namespace wash::detail {

/// The reference's Translation::program: its kernels in registration order.
std::string referenceProgram(const State &s);
/// After run.endStep: a checkpoint if one is due, the stop a signal asked for.
void checkpointAfterStep(Run &run, const State &s, std::uint64_t step);
/// With --restart, instead of the init kernels: the store and the run's state.
void restoreCheckpoint(Run &run, State &s);

} // namespace wash::detail
