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

/// Rows in a chunk: a chunk of a 3D frame with a dozen fields is about 0.5 MiB.
inline constexpr std::size_t spreadChunkRows = 4096;

/// Collective: `local` is this process's rows; `out` is the file on rank 0,
/// null on the others.
void writeCsvSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    std::ostream *out);
void writeVtpSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    const VtpOptions &options, std::ostream *out);

} // namespace wash::detail
