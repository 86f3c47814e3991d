//===- Pipeline.h - the translator, end to end ------------------*- C++ -*-===//
#pragma once

#include "wash/translator/InputFile.h"
#include "wash/translator/Options.h"

#include <string>
#include <vector>

namespace wash::tr {

/// What a translation read and found: `wash run` keys its cache on it.
struct TranslationFacts {
  /// Every file the translation read: the simulation, then each header it
  /// includes (the wash API's and the system's too).
  std::vector<InputFile> Inputs;
  unsigned Dimension = 0;
};

/// Parses, analyses and (with --dump-model) prints the simulation. Returns
/// the process exit status: 0, or 1 after any error; nothing is written to
/// stdout after an error. Facts, if given, is filled in on success.
int runPipeline(const Options &Opts, TranslationFacts *Facts = nullptr);

/// Parses the simulation and finds its dimension, translating nothing: what
/// an untranslated (reference) build needs to know. Returns 0, or 1 after an
/// error, reported at the user's location.
int inspectSimulation(const Options &Opts, TranslationFacts &Facts);

/// Flushes standard output; false, after a message, if any write to it
/// failed (a full disk, a closed pipe), so that the exit status says so.
bool checkedStdout();

} // namespace wash::tr
