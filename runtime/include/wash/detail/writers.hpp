//===- wash/detail/writers.hpp - CSV and VTK writers -------------*- C++ -*-===//
#pragma once

#include <wash/detail/frame.hpp>

#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
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
  /// A typed simulation's type names, in the field data as type_<name>.
  std::vector<std::string> typeNames;
};
void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time = std::nullopt);
void writeVtp(const Frame &frame, const Columns &columns, const VtpOptions &options,
              std::ostream &out);

/// The arrays of a .vtp but connectivity and offsets, in file order: Points
/// (pos with z = 0 in 2D), id, then the columns but pos.
struct VtpArray {
  std::string name;
  int components = 1;
  const Column *column = nullptr; ///< the column of a Values array
  enum Kind { Points, Id, Values } kind = Values;
};
std::vector<VtpArray> vtpArrays(const Frame &frame, const Columns &columns);
/// Appends to `out` the values of `array` for frame rows [begin, end).
void vtpArrayValues(const Frame &frame, const VtpArray &array, std::size_t begin, std::size_t end,
                    std::vector<double> &out);
/// Called with consecutive pieces of one array's values, in row order.
using VtpEmit = std::function<void(const double *values, std::size_t count)>;
/// Gives array `array` (an index into the arrays) to `emit`, all of it, once.
using VtpFeed = std::function<void(std::size_t array, const VtpEmit &emit)>;
/// The same file for `points` rows whose values `feed` gives array by array,
/// in file order: what a frame spread over processes is written with.
void writeVtp(std::uint64_t points, const std::vector<VtpArray> &arrays, const VtpOptions &options,
              const VtpFeed &feed, std::ostream &out);

/// Appends a CSV row: the id, then `width` values, comma-separated, newline.
void appendCsvRow(std::string &line, std::uint64_t id, const double *values, std::size_t width);
/// The CSV header row of `columns` (id first).
void writeCsvHeader(const Columns &columns, std::ostream &out);

/// `text` as XML attribute or element text: & < > " ' and tab, newline and
/// carriage return as references, so that a reader gives back `text` exactly;
/// other control characters, which XML 1.0 cannot hold, become U+FFFD.
std::string xmlText(std::string_view text);
/// `field` as one CSV field (RFC 4180): in double quotes, its quotes doubled,
/// when it holds a comma, a quote or a line break; else as it is.
std::string csvField(std::string_view field);

/// A ParaView collection (.pvd) listing (time, file) pairs.
void writePvd(const std::vector<std::pair<double, std::string>> &datasets, std::ostream &out);

} // namespace wash::detail
