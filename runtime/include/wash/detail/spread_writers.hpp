//===- wash/detail/spread_writers.hpp - CSV and VTK of a distributed frame -*- C++ -*-===//
//
// The files of writers.hpp for a frame whose rows are spread over processes
// (MPI), written by rank 0 from chunks it asks each process for in turn: rank
// 0 holds its own rows plus at most one chunk per process, never the frame.
// The bytes are those of writers.hpp for the frame of every process's rows in
// rank order (VTK) or sorted by id (CSV: a k-way merge of sorted chunks).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/processes.hpp>
#include <wash/detail/writers.hpp>

#include <ostream>

namespace wash::detail {

/// The bytes of a chunk: about 1 MiB, so that a frame of millions of
/// particles takes few round trips to rank 0 (latency, not bandwidth, bounds
/// a request-answer exchange). A chunk holds at least one row.
inline constexpr std::size_t spreadChunkBytes = std::size_t(1) << 20;
/// The CSV merge holds a chunk of every process on rank 0 at once: beyond 64
/// processes the chunks shrink so that they add up to 64 MiB, down to 64 KiB
/// each (reached at 1024 processes; past it, 64 KiB per process).
inline constexpr std::size_t spreadMergeBytes = std::size_t(64) << 20;
inline constexpr std::size_t spreadMinChunkBytes = std::size_t(64) << 10;

/// Collective: `local` is this process's rows; `out` is the file on rank 0,
/// null on the others; every process passes the same `chunkBytes`.
void writeCsvSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    std::ostream *out, std::size_t chunkBytes = spreadChunkBytes);
void writeVtpSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    const VtpOptions &options, std::ostream *out,
                    std::size_t chunkBytes = spreadChunkBytes);

} // namespace wash::detail
