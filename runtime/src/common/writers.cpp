#include <wash/detail/writers.hpp>

#include <charconv>
#include <iterator>
#include <string_view>

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

/// The numbers from, from + 1, ..., from + n - 1 (VTK connectivity, offsets).
void writeCount(std::ostream &out, std::size_t from, std::size_t n) {
  writeValues(out, n, [from](std::size_t k, Text &buf) {
    return written(buf, std::to_chars(buf, std::end(buf), from + k));
  });
}

void writeDataArray(std::ostream &out, const std::string &name, int components,
                    const std::vector<double> &values) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\""
      << components << "\" format=\"ascii\">\n          ";
  writeValues(out, values.size(),
              [&values](std::size_t k, Text &buf) { return exact(values[k], buf); });
  out << "\n        </DataArray>\n";
}

} // namespace

void writeCsv(const Frame &frame, std::ostream &out) {
  out << "id";
  for (const Column &column : frame.columns)
    for (const std::string &h : csvHeaders(column))
      out << ',' << h;
  out << '\n';
  std::string line;
  Text buf;
  for (std::size_t row : frame.orderById()) {
    line = std::to_string(frame.ids[row]);
    for (const Column &column : frame.columns)
      for (int c = 0; c < column.components; ++c)
        (line += ',') += exact(column.values[row * column.components + c], buf);
    line += '\n';
    out << line;
  }
}

void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time) {
  const std::size_t n = frame.size();
  const Column &pos = frame.columns.at(0);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n";
  if (time) {
    Text buf;
    out << "    <FieldData>\n"
        << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
           "format=\"ascii\">"
        << exact(*time, buf) << "</DataArray>\n"
        << "    </FieldData>\n";
  }
  out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\">\n"
      << "      <Points>\n";
  std::vector<double> points(3 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < pos.components; ++c)
      points[3 * p + c] = pos.values[p * pos.components + c];
  writeDataArray(out, "Points", 3, points);
  out << "      </Points>\n      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          ";
  writeCount(out, 0, n);
  out << "\n        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          ";
  writeCount(out, 1, n);
  out << "\n        </DataArray>\n      </Verts>\n      <PointData>\n";
  std::vector<double> ids(frame.ids.begin(), frame.ids.end());
  writeDataArray(out, "id", 1, ids);
  for (std::size_t k = 1; k < frame.columns.size(); ++k)
    writeDataArray(out, frame.columns[k].name, frame.columns[k].components,
                   frame.columns[k].values);
  out << "      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
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
