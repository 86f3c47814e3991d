//===- Pipeline.h - the translator, end to end ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Options.h"

namespace wash::tr {

/// Parses, analyses and (with --dump-model) prints the simulation. Returns
/// the process exit status: 0, or 1 after any error; nothing is written to
/// stdout after an error.
int runPipeline(const Options &Opts);

/// Flushes standard output; false, after a message, if any write to it
/// failed (a full disk, a closed pipe), so that the exit status says so.
bool checkedStdout();

} // namespace wash::tr
