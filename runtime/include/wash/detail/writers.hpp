//===- wash/detail/writers.hpp - CSV and VTK writers -------------*- C++ -*-===//
#pragma once

#include <wash/detail/frame.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace wash::detail {

/// The columns of a frame a file holds, "pos" first.
using Columns = std::vector<const Column *>;
/// The --dump's: every column but the frame-only ones (acc).
Columns dumpColumns(const Frame &frame);
/// A frame file's: every column, or with `fields` (--fields) "pos" and the
/// columns named there, in frame order. Names no column has are in `unknown`.
Columns frameColumns(const Frame &frame, const std::vector<std::string> &fields,
                     std::vector<std::string> *unknown = nullptr);

/// One header row, then one row per particle sorted by id; values with %.17g so
/// that a dump read back gives the same doubles. Without `columns`, the dump's.
void writeCsv(const Frame &frame, std::ostream &out);
void writeCsv(const Frame &frame, const Columns &columns, std::ostream &out);

/// A VTK XML PolyData (.vtp) file: points from "pos" (z = 0 in 2D), one vertex
/// cell per particle and every other column (and id) as point data; with a
/// time, a field-data TimeValue (ParaView and VTK's readers show it as the time).
struct VtpOptions {
  bool ascii = true; ///< else binary: every array raw in one appended block
  std::optional<double> time;
};
void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time = std::nullopt);
void writeVtp(const Frame &frame, const Columns &columns, const VtpOptions &options,
              std::ostream &out);

/// A ParaView collection (.pvd) listing (time, file) pairs.
void writePvd(const std::vector<std::pair<double, std::string>> &datasets, std::ostream &out);

} // namespace wash::detail
