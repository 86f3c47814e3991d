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
#include <memory>
#include <optional>
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

/// The error for a std::bad_alloc while allocating `count` items of `bytesEach`
/// bytes for `what`: "out of memory allocating N particles x M bytes (X GiB)
/// for ...", so that a run too large for the machine says how large it was.
RunError outOfMemory(const std::string &what, std::uint64_t count, std::uint64_t bytesEach);

/// How far the run has got, for the message of a failure nothing else names.
struct RunStage {
  std::uint64_t particles = 0;
  std::uint64_t step = 0; ///< 0: set-up and init kernels
  bool begun = false;     ///< the init kernels are done
  std::uint64_t steps = 0;
  /// "in step 3 (1000 particles)", "before the first step", ...
  std::string describe() const;
};
RunStage &runStage();

/// With --output-every K > 0: step 0, every K-th step and the last step.
/// With K = 0: the last step only.
bool frameDue(const RunOptions &options, std::uint64_t step, std::uint64_t lastStep);

/// Why `name` cannot be the base name of output files (with a '/' it could
/// leave the output directory: "../x", "/abs/x"), or an empty string if it can.
std::string checkOutputName(const std::string &name);

/// About the size of `frame` written as VTK or CSV, for RunOutput::reserve;
/// with `rows`, of a frame of that many rows like it (an MPI rank's share).
std::uint64_t frameBytesEstimate(const Frame &frame);
std::uint64_t frameBytesEstimate(const Frame &frame, std::uint64_t rows);

class Hdf5Series;
class FolderLock;

/// Every file is written to a temporary file beside it and renamed into place,
/// so a failed write (a full disk) leaves no truncated file behind; the HDF5
/// file of --format hdf5 is renamed into place when the run finishes.
///
/// In a run spread over processes (processes(), MPI) every process has one
/// and calls writeFrame and finish with its own rows, collectively: rank 0
/// writes CSV, VTK and the dump from chunks of the others' rows; for HDF5
/// each process writes its rows itself.
class RunOutput {
public:
  /// Checks the base name, creates the output directory and checks that it
  /// and the --dump file's directory are writable (throws RunError); in a
  /// distributed run, rank 0 only.
  RunOutput(const RunOptions &options, std::string baseName);
  ~RunOutput();

  /// Checks that `bytes` (about a frame) can be allocated in the output
  /// directory and beside the --dump file (throws RunError): a disk that is
  /// already full stops the run before its first step.
  void reserve(std::uint64_t bytes);
  /// Throws RunError if --fields names a field `frame` does not have.
  void checkFields(const Frame &frame) const;

  bool frameDue(std::uint64_t step, std::uint64_t lastStep) const {
    return detail::frameDue(options_, step, lastStep);
  }
  /// With a simulated time, VTK frames carry it (TimeValue); the .pvd series
  /// lists every frame at its time once a frame was written `seriesByTime`
  /// (time steps are set), else at its step number.
  void writeFrame(std::uint64_t step, const Frame &frame, std::optional<double> time = std::nullopt,
                  bool seriesByTime = false);
  /// Writes the .pvd series (VTK) and the --dump file, if asked for.
  void finish(const Frame &finalFrame);
  /// A run stopped by a signal: the HDF5 file as far as it got renamed into
  /// place (collective under MPI); the .pvd is current after every frame.
  void closeSeries();

  const std::string &directory() const { return options_.outDir; }

  /// A frame of the series (.pvd, or groups of the HDF5 file); a checkpoint
  /// saves the series so far, and a restarted run continues it.
  struct Written {
    std::uint64_t step;
    double time;
    std::string file;
  };
  const std::vector<Written> &written() const { return written_; }
  bool seriesByTime() const { return seriesByTime_; }
  /// A restart: the frames of this format in `written` stay in the series;
  /// the .pvd is rewritten to list them, the HDF5 file continued after them
  /// (Hdf5Opener). Collective under MPI.
  void continueSeries(std::vector<Written> written, bool seriesByTime);

private:
  std::string framePath(std::uint64_t step) const;
  /// The .pvd of the frames so far (rank 0, VTK).
  void writeSeries() const;
  /// Opens the HDF5 file, continuing the frames of written_ on a restart.
  void openHdf5(bool restart);
  std::string probePath() const;

  std::vector<std::unique_ptr<FolderLock>> locks_; ///< the folders written (released last)
  RunOptions options_;
  std::string baseName_;
  std::vector<Written> written_;
  bool seriesByTime_ = false;
  bool root_;                        ///< writes the CSV, VTK and dump files
  std::unique_ptr<Hdf5Series> hdf5_; ///< --format hdf5, from the first frame on
};

/// Writes frame as CSV to path (throws RunError if it cannot).
void writeCsvFile(const Frame &frame, const std::string &path);

} // namespace wash::detail
