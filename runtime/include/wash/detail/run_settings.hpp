//===- wash/detail/run_settings.hpp - what main configured -------*- C++ -*-===//
//
// The one store behind wash/settings.hpp, shared by the reference runtime and
// every backend: the set_* calls and the run's start-up checks (run.hpp) then
// exist once, so every runtime accepts and rejects the same settings.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/box.hpp>
#include <wash/detail/options.hpp>
#include <wash/detail/search.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace wash::detail {

struct RunSettings {
  std::optional<bool> useFloat; ///< set_precision; unset means double
  SearchRule search;
  std::string simulationName = "wash";
  std::string outputFileName;
  std::optional<std::uint64_t> maxIterations;
  Box box;
  /// The program's dimension, which set_bounding_box checks against: set
  /// before main runs by the reference runtime (its WASH_DIM) or by a
  /// generated program's storage header.
  int dimensions = 0;
  bool stopRequested = false; ///< by wash::stop() in a void kernel

  /// The base name of output files: the output file name, else the simulation's.
  const std::string &outputBaseName() const {
    return outputFileName.empty() ? simulationName : outputFileName;
  }
};

/// Function-local statics, so that static initialisers may use them.
RunSettings &runSettings();
/// The program options __wrap_main found.
RunOptions &programOptions();

} // namespace wash::detail
