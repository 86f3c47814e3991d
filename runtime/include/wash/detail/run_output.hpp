//===- wash/detail/run_output.hpp - frames, series and dump of a run -*- C++ -*-===//
//
// Decides when frames are written and writes them, the .pvd series and the
// --dump file. Shared by every runtime so that all write the same files.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/frame.hpp>
#include <wash/detail/options.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace wash::detail {

/// A failure of the run (I/O, non-finite state, misuse); the message is ready to print.
struct RunError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A misuse of the API whose message already starts with `file:line:col: error:`.
struct UsageError : RunError {
  using RunError::RunError;
};

/// With --output-every K > 0: step 0, every K-th step and the last step.
/// With K = 0: the last step only.
bool frameDue(const RunOptions &options, std::uint64_t step, std::uint64_t lastStep);

class RunOutput {
public:
  /// Creates the output directory and checks that it is writable (throws RunError).
  RunOutput(const RunOptions &options, std::string baseName);

  bool frameDue(std::uint64_t step, std::uint64_t lastStep) const {
    return detail::frameDue(options_, step, lastStep);
  }
  void writeFrame(std::uint64_t step, const Frame &frame);
  /// Writes the .pvd series (VTK) and the --dump file, if asked for.
  void finish(const Frame &finalFrame);

  const std::string &directory() const { return options_.outDir; }

private:
  std::string framePath(std::uint64_t step) const;

  RunOptions options_;
  std::string baseName_;
  std::vector<std::pair<double, std::string>> written_;
};

/// Writes frame as CSV to path (throws RunError if it cannot).
void writeCsvFile(const Frame &frame, const std::string &path);

} // namespace wash::detail
