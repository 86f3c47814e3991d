//===- wash/detail/frame.hpp - particle data handed to the writers -*- C++ -*-===//
//
// A Frame is a column view of the particle state that every runtime (reference
// or generated) fills in the same order, so that all of them write the same
// files: id, pos, vel, density, mass, smoothing_length, then every force.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace wash::detail {

struct Column {
  std::string name;
  int components = 1;         ///< 1 for scalars, the dimension for vectors
  std::vector<double> values; ///< particle-major: values[p * components + c]
  bool inDump = true;         ///< false: in frames only, never in --dump (acc)
};

struct Frame {
  int dimensions = 2;
  std::vector<std::uint64_t> ids;
  std::vector<Column> columns; ///< columns[0] is "pos"
  /// A typed simulation's particle types, by index (its "type" column).
  std::vector<std::string> typeNames;

  std::size_t size() const { return ids.size(); }
  /// Positions of the rows in ascending id order.
  std::vector<std::size_t> orderById() const;
};

/// CSV header names of a column: pos -> x,y[,z]; vel -> vx,vy[,vz];
/// another vector v -> v_x,v_y[,v_z]; a scalar keeps its name.
std::vector<std::string> csvHeaders(const Column &column);

/// Returns "" if every value is finite, else a message naming the first bad one.
std::string findNonFinite(const Frame &frame);
/// That message: "field 'density' of particle 7 is inf".
std::string nonFiniteMessage(const std::string &field, std::uint64_t id, double value);

} // namespace wash::detail
