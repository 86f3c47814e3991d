//===- Pipeline.h - the translator, end to end ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/Options.h"

namespace wash::tr {

/// Parses, analyses and (with --dump-model) prints the simulation. Returns
/// the process exit status: 0, or 1 after any error; nothing is written to
/// stdout after an error.
int runPipeline(const Options &Opts);

} // namespace wash::tr
