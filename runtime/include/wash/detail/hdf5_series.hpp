//===- wash/detail/hdf5_series.hpp - --format hdf5 (H5Part) ----*- C++ -*-===//
//
// One HDF5 file per run in the H5Part layout: a group Step#<k> per frame k
// (0, 1, ...) with attributes time, step and particle_count, and one
// one-dimensional dataset per output value, rows in ascending id order.
// Implemented twice from runtime/src/hdf5/h5part.cpp: on the serial HDF5
// library (reference, serial, openmp) and on parallel HDF5 (mpi), where each
// rank writes its own rows. Which one a program has is set by its entry point
// (hdf5Opener), so the shared runtime links neither.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/frame.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace wash::detail {

/// One dataset of a step: component `component` of `column`, or zeros
/// (`column` null: z and vz of a 2D run, which H5Part readers expect).
struct Hdf5Dataset {
  std::string name;
  const Column *column = nullptr;
  int component = 0;
};

class Hdf5Series {
public:
  virtual ~Hdf5Series() = default;
  /// Appends the next Step#<k> group. Collective under MPI: every rank passes
  /// its own rows, in any order, and the same step, time and datasets.
  virtual void write(std::uint64_t step, double time, const Frame &rows,
                     const std::vector<Hdf5Dataset> &datasets) = 0;
  /// Closes the file (collective under MPI) and renames it into place.
  virtual void close() = 0;
};

/// A frame of a series a restart continues: group Step#k holds iteration
/// `step` at `time`.
struct Hdf5Step {
  std::uint64_t step = 0;
  double time = 0.0;
};

/// Creates `partial` (renamed onto `path` by close()); throws RunError. A
/// failed write throws RunError too, having removed `partial`.
/// A restart passes the frames of the series before its checkpoint as `keep`:
/// then if `path` exists, its groups Step#0 ... must be those frames (else
/// RunError, `path` untouched); `partial` starts as a copy of it without the
/// groups after them, and the next write is Step#<keep.size()>. Without
/// `path`, or with `keep` empty, `partial` starts empty, at Step#0.
using Hdf5Opener = std::unique_ptr<Hdf5Series> (*)(const std::string &path,
                                                   const std::string &partial,
                                                   const std::vector<Hdf5Step> &keep);
/// The program's HDF5 flavour; null where its entry point set none (unit tests).
Hdf5Opener &hdf5Opener();

/// The two flavours, one per library built from h5part.cpp.
std::unique_ptr<Hdf5Series> openSerialHdf5Series(const std::string &path,
                                                 const std::string &partial,
                                                 const std::vector<Hdf5Step> &keep);
std::unique_ptr<Hdf5Series> openParallelHdf5Series(const std::string &path,
                                                   const std::string &partial,
                                                   const std::vector<Hdf5Step> &keep);

} // namespace wash::detail
