//===- wash/random.hpp - random numbers that every build agrees on -*- C++ -*-===//
//
// A counter-based generator: a number is a hash of (key, step, stream), with no
// state that calls advance. The same key in the same step gives the same number
// on the reference and every backend, at any thread or rank count, in any call
// order, and after a restart from a checkpoint. docs/api.md, "Random numbers".
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>

namespace wash {

/// A uniform number in [0, 1), a multiple of 2^-53, for `key` in the current
/// step. The key names what the number is for, typically p.get_id() in a
/// kernel or a loop index in an init kernel; `stream` tells apart several
/// numbers for one key in one step (one per axis, say). In main and init
/// kernels the step is 0; the run's steps are 1, 2, ..., so a key draws a
/// new number every step.
double random(std::uint64_t key, std::uint64_t stream = 0);

/// A standard normal number (mean 0, variance 1) for `key` in the current step,
/// by the Box-Muller transform of two uniform numbers of (key, step, stream).
/// It calls the C library's log and cos, so it is identical wherever the same
/// library runs (every backend and process of one machine).
double random_normal(std::uint64_t key, std::uint64_t stream = 0);

} // namespace wash
