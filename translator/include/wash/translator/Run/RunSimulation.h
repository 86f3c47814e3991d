//===- RunSimulation.h - wash run -------------------------------*- C++ -*-===//
//
// `wash run SIM.cpp`: translate, configure and build into the cache (only
// if the build there is not current), then run the program in this
// process's place.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/Backends.h"

#include <optional>
#include <string>
#include <vector>

namespace wash::tr {

struct RunRequest {
  std::string Source; ///< The simulation file.
  /// The backend to translate for; none for the untranslated (reference)
  /// program.
  std::optional<Backend> Target;
  /// Processes to start with mpirun (a distributed backend); 0 runs the
  /// program directly.
  unsigned Ranks = 0;
  /// Folders the simulation's headers are included from (-I).
  std::vector<std::string> IncludeDirs;
  std::vector<std::string> ProgramArgs; ///< After `--`.
  std::string ExecutablePath;           ///< wash itself.
};

/// Builds the program if need be and runs it. Returns only if it does not
/// run: 1 after a failed translation or build, saying why.
int runSimulation(const RunRequest &R);

} // namespace wash::tr
