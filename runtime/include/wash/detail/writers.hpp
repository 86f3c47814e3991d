//===- wash/detail/writers.hpp - CSV and VTK writers -------------*- C++ -*-===//
#pragma once

#include <wash/detail/frame.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace wash::detail {

/// One header row, then one row per particle sorted by id; values with %.17g so
/// that a dump read back gives the same doubles.
void writeCsv(const Frame &frame, std::ostream &out);

/// A VTK XML PolyData (.vtp) file: points from "pos" (z = 0 in 2D), one vertex
/// cell per particle and every other column (and id) as point data; with a
/// time, a field-data TimeValue (ParaView and VTK's readers show it as the time).
void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time = std::nullopt);

/// A ParaView collection (.pvd) listing (time, file) pairs.
void writePvd(const std::vector<std::pair<double, std::string>> &datasets, std::ostream &out);

} // namespace wash::detail
