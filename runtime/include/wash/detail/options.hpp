//===- wash/detail/options.hpp - program options of every wash program -*- C++ -*-===//
//
// Every wash program, reference or generated, accepts the same options. They
// are removed from argv before the simulation's own main sees it.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace wash::detail {

enum class OutputFormat { Vtk, Csv, Hdf5 };

struct RunOptions {
  std::optional<std::uint64_t> steps; ///< overrides set_max_iterations
  std::string outDir = "out";
  std::uint64_t outputEvery = 0; ///< 0: final state only
  OutputFormat format = OutputFormat::Vtk;
  std::string dumpPath; ///< empty: no dump
  bool quiet = false;
  bool help = false;
  bool profile = false;            ///< --profile: where the steps' time went
  std::optional<double> endTime;   ///< stop after the iteration that reaches it
  std::optional<double> outputDt;  ///< a frame whenever the time crosses a multiple
  bool vtkAscii = false;           ///< --vtk-encoding ascii (default binary)
  std::vector<std::string> fields; ///< --fields: what frames hold (empty: everything)
  // Checkpoints (docs/semantics.md, "Checkpoint and restart").
  std::uint64_t checkpointEvery = 0;  ///< --checkpoint-every K (0: none by steps)
  std::optional<double> checkpointDt; ///< --checkpoint-dt T (simulated time)
  std::string checkpointDir;          ///< empty: <outDir>/checkpoints
  std::uint64_t keepCheckpoints = 2;  ///< --keep-checkpoints N (at least 1)
  std::string restartPath;            ///< --restart PATH (empty: a fresh run)
  std::optional<double> watchdog;     ///< --watchdog SECONDS (MPI; 0: off; unset: default)
};

struct ParsedArgs {
  RunOptions options;
  std::vector<char *> userArgv; ///< argv[0] and everything that is not a wash option
};

/// Thrown for a bad command line; the message is ready to print.
struct OptionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Splits argv into wash options and the simulation's own arguments. Accepts
/// `--opt value` and `--opt=value`; `--` ends the wash options.
ParsedArgs parseProgramOptions(int argc, char **argv);

/// The text --help prints.
std::string usageText(const std::string &program);

} // namespace wash::detail
