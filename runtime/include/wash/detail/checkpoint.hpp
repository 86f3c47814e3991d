//===- wash/detail/checkpoint.hpp - checkpoint files, shared by every runtime -*- C++ -*-===//
//
// A checkpoint is a folder `checkpoint_<iteration>` holding one shard per
// process (`shard_<k>.wck`: that process's particles, column by column, at
// storage precision) and an index (`index.wck`: identity, iteration, time,
// variables, output bookkeeping). It is written as `<name>.partial`, every
// file under a temporary name renamed into place, the index last, and the
// folder renamed once complete: a folder without `.partial` and with an index
// is complete. Every file ends with a checksum of all its bytes, and the
// index holds each shard's: a reader refuses a truncated or corrupted file,
// another program's checkpoint, or a shard of another checkpoint, with the
// reason. The format is in docs/semantics.md, "Checkpoint and restart".
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/run_output.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace wash::detail {

/// The exit status of a run stopped by SIGTERM or SIGINT after writing a
/// checkpoint (EX_TEMPFAIL: try again, with --restart).
inline constexpr int interruptedExitStatus = 75;

/// The run stopped on a signal, its checkpoint written; the message (empty on
/// all but the writing process) says where.
struct Interrupted : RunError {
  using RunError::RunError;
};

/// A stored column: its name and the bytes of one element.
struct CheckpointField {
  std::string name;
  std::uint32_t elementBytes = 0;
  bool operator==(const CheckpointField &) const = default;
};

/// Which kind of program wrote a checkpoint: the reference runtime's
/// checkpoints hold its own store, a translated program's its columns, so
/// neither restarts from the other's. Version 2 files do not say (Unknown).
enum class CheckpointWriter : std::uint8_t { Unknown = 0, Reference = 1, Translated = 2 };

/// What a checkpoint must match to be restarted by this program.
struct CheckpointIdentity {
  std::string simulation; ///< set_simulation_name
  std::string program;    ///< the kernels and columns (Translation::program, or the reference's)
  std::uint32_t dimensions = 0;
  bool useFloat = false;
  std::vector<CheckpointField> fields; ///< every stored column, in storage order
  /// Consulted only to say why two programs differ.
  CheckpointWriter writer = CheckpointWriter::Unknown;
};

/// One process's particles: `particles` rows of each column.
struct Shard {
  struct Column {
    CheckpointField field;
    std::vector<char> bytes;
  };
  std::uint64_t particles = 0;
  std::vector<Column> columns;
};

/// Everything besides the particles that the next iteration depends on.
struct CheckpointState {
  std::uint64_t iteration = 0;
  double time = 0.0, timeStep = 0.0;
  bool timeStepSet = false, stopRequested = false;
  std::vector<std::pair<std::string, double>> variables;
  std::uint64_t nextOutput = 0,
                nextCheckpoint = 0; ///< the next --output-dt / --checkpoint-dt multiple
  bool seriesByTime = false;
  std::vector<RunOutput::Written> frames; ///< the .pvd series so far
  std::uint32_t shards = 1;
  std::uint64_t particles = 0;
  /// Each shard's checksum, binding the index to its shards.
  std::vector<std::uint64_t> shardChecksums;
};

/// Where checkpoints go: --checkpoint-dir, else <out>/checkpoints.
std::string checkpointDirectory(const RunOptions &options);

/// `<dir>/checkpoint_<iteration>` and its parts.
std::string checkpointFolder(const std::string &dir, std::uint64_t iteration);
std::string partialFolder(const std::string &folder);
std::string shardPath(const std::string &folder, std::uint32_t shard);
std::string indexPath(const std::string &folder);

/// Removes a stale `partial` folder and creates it afresh (the writing process).
void beginCheckpoint(const std::string &partial);
/// Writes a file under a temporary name, renamed into place (throws RunError).
/// writeShard returns the shard's checksum, which its index is written with.
std::uint64_t writeShard(const std::string &path, const CheckpointIdentity &id, const Shard &shard);
void writeIndex(const std::string &path, const CheckpointIdentity &id,
                const CheckpointState &state);
/// Renames `partial` to `folder` and removes the oldest complete checkpoints
/// beside it beyond the newest `keep`.
void completeCheckpoint(const std::string &partial, const std::string &folder, std::uint64_t keep);

/// `path` itself if it is a checkpoint, else the newest complete checkpoint
/// in the folder `path` (throws RunError if there is none).
std::string resolveRestart(const std::string &path);
/// Reads and checks a file of checkpoint `folder` (throws RunError, saying why);
/// a shard must be the one the index names (`index.shardChecksums`).
CheckpointState readIndex(const std::string &folder, const CheckpointIdentity &expected);
Shard readShard(const std::string &folder, std::uint32_t shard, const CheckpointIdentity &expected,
                const CheckpointState &index);

/// The checksum a checkpoint file ends with, of all its bytes before it.
std::uint64_t checkpointChecksum(const void *data, std::size_t bytes);

/// A short hash of `text`, for CheckpointIdentity::program.
std::string identityHash(const std::string &text);

/// From the first step on, SIGTERM and SIGINT set a flag the run checks after
/// each iteration; a second one ends the program at once.
void watchStopSignals();
/// The signal received (0: none).
int stopSignal();

} // namespace wash::detail
