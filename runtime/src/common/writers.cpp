#include <wash/detail/writers.hpp>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstdint>
#include <iterator>
#include <string_view>
#include <type_traits>

namespace wash::detail {
namespace {

using Text = char[32];

/// What to_chars wrote at the start of buf.
std::string_view written(const Text &buf, std::to_chars_result r) {
  return {buf, std::size_t(r.ptr - buf)};
}

/// Text that reads back as the same double: exactly printf's "%.17g" (the C++
/// standard defines to_chars with a precision so), at a fifth of its cost,
/// which matters when a frame holds millions of values.
std::string_view exact(double v, Text &buf) {
  return written(buf, std::to_chars(buf, std::end(buf), v, std::chars_format::general, 17));
}

/// n values separated by single spaces, text(k, buf) giving the k-th; written
/// a block at a time rather than a value at a time.
template <typename ValueText> void writeValues(std::ostream &out, std::size_t n, ValueText text) {
  std::string block;
  Text buf;
  for (std::size_t k = 0; k < n; ++k) {
    if (k)
      block += ' ';
    block += text(k, buf);
    if (block.size() >= 1 << 16) {
      out << block;
      block.clear();
    }
  }
  out << block;
}

} // namespace

Columns dumpColumns(const Frame &frame) {
  Columns columns;
  for (const Column &column : frame.columns)
    if (column.inDump)
      columns.push_back(&column);
  return columns;
}

Columns frameColumns(const Frame &frame, const std::vector<std::string> &fields,
                     std::vector<std::string> *unknown) {
  Columns columns;
  for (const Column &column : frame.columns)
    if (fields.empty() || &column == &frame.columns.at(0) ||
        std::find(fields.begin(), fields.end(), column.name) != fields.end())
      columns.push_back(&column);
  if (unknown)
    for (const std::string &name : fields)
      if (name != "id" && std::none_of(frame.columns.begin(), frame.columns.end(),
                                       [&](const Column &c) { return c.name == name; }))
        unknown->push_back(name);
  return columns;
}

void writeCsv(const Frame &frame, std::ostream &out) { writeCsv(frame, dumpColumns(frame), out); }

void writeCsv(const Frame &frame, const Columns &columns, std::ostream &out) {
  out << "id";
  for (const Column *column : columns)
    for (const std::string &h : csvHeaders(*column))
      out << ',' << h;
  out << '\n';
  std::string line;
  Text buf;
  for (std::size_t row : frame.orderById()) {
    line = std::to_string(frame.ids[row]);
    for (const Column *column : columns)
      for (int c = 0; c < column->components; ++c)
        (line += ',') += exact(column->values[row * column->components + c], buf);
    line += '\n';
    out << line;
  }
}

namespace {

/// The arrays of a binary .vtp, written after the XML in one appended block:
/// each a UInt64 byte count, then its bytes, at the offset its DataArray names.
class Appended {
public:
  /// The attributes of a DataArray whose values follow in the block.
  template <typename T> std::string add(const std::vector<T> &values) {
    blocks_.push_back({reinterpret_cast<const char *>(values.data()), values.size() * sizeof(T)});
    std::string at = "format=\"appended\" offset=\"" + std::to_string(size_) + "\"";
    size_ += sizeof(std::uint64_t) + values.size() * sizeof(T);
    return at;
  }
  void write(std::ostream &out) const {
    out << "  <AppendedData encoding=\"raw\">\n   _";
    for (const auto &[data, bytes] : blocks_) {
      const std::uint64_t count = bytes;
      out.write(reinterpret_cast<const char *>(&count), sizeof count);
      out.write(data, std::streamsize(bytes));
    }
    out << "\n  </AppendedData>\n";
  }

private:
  std::vector<std::pair<const char *, std::size_t>> blocks_;
  std::uint64_t size_ = 0;
};

template <typename T> const char *vtkType();
template <> const char *vtkType<double>() { return "Float64"; }
template <> const char *vtkType<std::int64_t>() { return "Int64"; }

/// One DataArray: inline text, or a reference into the appended block.
template <typename T>
void dataArray(std::ostream &out, const std::string &name, int components,
               const std::vector<T> &values, Appended *appended) {
  out << "        <DataArray type=\"" << vtkType<T>() << "\" Name=\"" << name << "\"";
  if (components)
    out << " NumberOfComponents=\"" << components << "\"";
  if (appended) {
    out << " " << appended->add(values) << "/>\n";
    return;
  }
  out << " format=\"ascii\">\n          ";
  writeValues(out, values.size(), [&values](std::size_t k, Text &buf) {
    if constexpr (std::is_same_v<T, double>)
      return exact(values[k], buf);
    else
      return written(buf, std::to_chars(buf, std::end(buf), values[k]));
  });
  out << "\n        </DataArray>\n";
}

} // namespace

void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time) {
  writeVtp(frame, frameColumns(frame, {}), VtpOptions{.ascii = true, .time = time}, out);
}

void writeVtp(const Frame &frame, const Columns &columns, const VtpOptions &options,
              std::ostream &out) {
  static_assert(std::endian::native == std::endian::little, "binary VTK is written little-endian");
  const std::size_t n = frame.size();
  const Column &pos = frame.columns.at(0);
  Appended block;
  Appended *appended = options.ascii ? nullptr : &block;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"" << (appended ? "1.0" : "0.1")
      << "\" byte_order=\"LittleEndian\"" << (appended ? " header_type=\"UInt64\"" : "") << ">\n"
      << "  <PolyData>\n";
  if (options.time || !frame.typeNames.empty()) {
    Text buf;
    out << "    <FieldData>\n";
    if (options.time)
      out << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
             "format=\"ascii\">"
          << exact(*options.time, buf) << "</DataArray>\n";
    // A typed simulation: type_<name> holds the index its "type" column uses.
    for (std::size_t t = 0; t < frame.typeNames.size(); ++t)
      out << "      <DataArray type=\"Int64\" Name=\"type_" << frame.typeNames[t]
          << "\" NumberOfTuples=\"1\" format=\"ascii\">" << t << "</DataArray>\n";
    out << "    </FieldData>\n";
  }
  out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\">\n"
      << "      <Points>\n";
  std::vector<double> points(3 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < pos.components; ++c)
      points[3 * p + c] = pos.values[p * pos.components + c];
  dataArray(out, "Points", 3, points, appended);
  out << "      </Points>\n      <Verts>\n";
  std::vector<std::int64_t> connectivity(n), offsets(n);
  for (std::size_t p = 0; p < n; ++p) {
    connectivity[p] = std::int64_t(p);
    offsets[p] = std::int64_t(p + 1);
  }
  dataArray(out, "connectivity", 0, connectivity, appended);
  dataArray(out, "offsets", 0, offsets, appended);
  out << "      </Verts>\n      <PointData>\n";
  std::vector<double> ids(frame.ids.begin(), frame.ids.end());
  dataArray(out, "id", 1, ids, appended);
  for (const Column *column : columns)
    if (column != &pos)
      dataArray(out, column->name, column->components, column->values, appended);
  out << "      </PointData>\n    </Piece>\n  </PolyData>\n";
  if (appended)
    block.write(out);
  out << "</VTKFile>\n";
}

void writePvd(const std::vector<std::pair<double, std::string>> &datasets, std::ostream &out) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  Text buf;
  for (const auto &[time, file] : datasets)
    out << "    <DataSet timestep=\"" << exact(time, buf) << "\" part=\"0\" file=\"" << file
        << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
}

} // namespace wash::detail
