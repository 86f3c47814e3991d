//===- wash/backend/checkpoint.hpp - checkpoint and restart of generated programs -*- C++ -*-===//
//
// What a generated start() calls after every step and, with --restart,
// instead of the init kernels. `columns(f)` calls f(name, column) for every
// column of the generated storage; only the owned rows are saved (no images,
// no halo). Each process writes one shard; the writing process writes the
// index and completes the folder (wash/detail/checkpoint.hpp). A restart at
// any process count reads shards [k*S/R, (k+1)*S/R) on process k of R, and
// the backend's restore() moves the particles to their owners.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/backend/run.hpp>
#include <wash/detail/checkpoint.hpp>
#include <wash/detail/processes.hpp>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

namespace wash::backend {

template <typename Columns> std::vector<detail::CheckpointField> checkpointFields(Columns columns) {
  std::vector<detail::CheckpointField> fields;
  columns([&](const char *name, auto &column) {
    fields.push_back({name, std::uint32_t(sizeof(column[0]))});
  });
  return fields;
}

/// Writes a checkpoint of the state after `step` (collective).
template <typename B, typename Columns>
void writeCheckpoint(const B &backend, Run &run, std::uint64_t step, std::uint64_t particles,
                     Columns columns) {
  const detail::ProfileScope profiled("checkpoint");
  const auto start = std::chrono::steady_clock::now();
  const std::string folder = detail::checkpointFolder(run.checkpointDir(), step);
  const std::string partial = detail::partialFolder(folder);
  const bool writer = backend.rankIndex() == 0;
  if (writer)
    detail::beginCheckpoint(partial);
  backend.barrier();
  const std::vector<Index> &rows = backend.owned();
  detail::Shard shard;
  shard.particles = rows.size();
  columns([&](const char *name, auto &column) {
    constexpr std::size_t bytes = sizeof(column[0]);
    detail::Shard::Column c{{name, std::uint32_t(bytes)}, std::vector<char>(rows.size() * bytes)};
    for (std::size_t k = 0; k < rows.size(); ++k)
      std::memcpy(c.bytes.data() + k * bytes, &column[rows[k]], bytes);
    shard.columns.push_back(std::move(c));
  });
  const detail::CheckpointIdentity id = run.identity(checkpointFields(columns));
  const std::uint64_t checksum =
      detail::writeShard(detail::shardPath(partial, std::uint32_t(backend.rankIndex())), id, shard);
  // Every shard is in place, and its checksum (for the index) known to all.
  const detail::Processes *processes = detail::processes();
  const std::vector<std::uint64_t> checksums =
      backend.rankCount() > 1 ? processes->allgather(checksum) : std::vector{checksum};
  if (writer) {
    detail::CheckpointState state =
        run.checkpointState(step, std::uint32_t(backend.rankCount()), particles);
    state.shardChecksums = checksums;
    detail::writeIndex(detail::indexPath(partial), id, state);
    detail::completeCheckpoint(partial, folder, detail::programOptions().keepCheckpoints);
  }
  backend.barrier(); // complete before any process goes on (or stops)
  run.checkpointWritten(
      folder, step,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

/// After run.endStep: a checkpoint if one is due, and the stop a signal asked
/// for (every process decides alike: one collective flag per step).
template <typename B, typename Columns>
void afterStep(const B &backend, Run &run, std::uint64_t step, std::uint64_t particles,
               Columns columns) {
  const bool stop = backend.anyRank(detail::stopSignal() != 0);
  if (run.checkpointDue() || stop)
    writeCheckpoint(backend, run, step, particles, columns);
  if (stop) {
    run.stopped();
    const std::string folder = detail::checkpointFolder(run.checkpointDir(), step);
    throw detail::Interrupted(backend.rankIndex() != 0
                                  ? ""
                                  : "stopped by a signal after iteration " + std::to_string(step) +
                                        "; checkpoint written to " + folder +
                                        " (continue with --restart " + folder + ")");
  }
}

/// With --restart: reads this process's shards into P (whose columns
/// `columns` visits), restores the run's state (Run::firstStep), and returns
/// how many particles there are in all.
template <typename B, typename Particles, typename Columns, typename CellSize>
std::uint64_t restoreCheckpoint(B &backend, Run &run, Particles &P, Columns columns,
                                CellSize cellSize) {
  const auto start = std::chrono::steady_clock::now();
  const detail::CheckpointIdentity id = run.identity(checkpointFields(columns));
  const std::string folder = detail::resolveRestart(detail::programOptions().restartPath);
  const detail::CheckpointState saved = detail::readIndex(folder, id);
  const std::uint64_t R = std::uint64_t(backend.rankCount()),
                      k = std::uint64_t(backend.rankIndex());
  std::vector<detail::Shard> shards;
  std::uint64_t local = 0;
  for (std::uint64_t s = k * saved.shards / R; s < (k + 1) * saved.shards / R; ++s) {
    shards.push_back(detail::readShard(folder, std::uint32_t(s), id, saved));
    local += shards.back().particles;
  }
  columns([&](const char *name, auto &column) {
    constexpr std::size_t bytes = sizeof(column[0]);
    column.resize(local);
    std::size_t row = 0;
    for (const detail::Shard &shard : shards) {
      const detail::Shard::Column *found = nullptr;
      for (const detail::Shard::Column &c : shard.columns)
        if (c.field.name == name && c.field.elementBytes == bytes)
          found = &c;
      if (!found)
        throw detail::RunError("cannot restart from checkpoint '" + folder +
                               "': a shard has no column '" + name + "'");
      if (shard.particles)
        std::memcpy(static_cast<void *>(&column[row]), found->bytes.data(), found->bytes.size());
      row += shard.particles;
    }
  });
  if (backend.sumOverRanks(local) != saved.particles)
    throw detail::RunError("cannot restart from checkpoint '" + folder + "': its shards hold " +
                           std::to_string(backend.sumOverRanks(local)) + " particles, its index " +
                           std::to_string(saved.particles));
  const std::uint64_t particles = backend.restore(P, cellSize);
  run.resume(saved, particles, folder,
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return particles;
}

} // namespace wash::backend
