#include <wash/detail/writers.hpp>

#include <cstdio>

namespace wash::detail {
namespace {

/// Shortest text that reads back as the same double.
std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void writeDataArray(std::ostream &out, const std::string &name, int components,
                    const std::vector<double> &values) {
  out << "        <DataArray type=\"Float64\" Name=\"" << name
      << "\" NumberOfComponents=\"" << components << "\" format=\"ascii\">\n          ";
  for (std::size_t k = 0; k < values.size(); ++k)
    out << exact(values[k]) << (k + 1 < values.size() ? " " : "");
  out << "\n        </DataArray>\n";
}

} // namespace

void writeCsv(const Frame &frame, std::ostream &out) {
  out << "id";
  for (const Column &column : frame.columns)
    for (const std::string &h : csvHeaders(column))
      out << ',' << h;
  out << '\n';
  for (std::size_t row : frame.orderById()) {
    out << frame.ids[row];
    for (const Column &column : frame.columns)
      for (int c = 0; c < column.components; ++c)
        out << ',' << exact(column.values[row * column.components + c]);
    out << '\n';
  }
}

void writeVtp(const Frame &frame, std::ostream &out) {
  const std::size_t n = frame.size();
  const Column &pos = frame.columns.at(0);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <PolyData>\n"
      << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\">\n"
      << "      <Points>\n";
  std::vector<double> points(3 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < pos.components; ++c)
      points[3 * p + c] = pos.values[p * pos.components + c];
  writeDataArray(out, "Points", 3, points);
  out << "      </Points>\n      <Verts>\n"
      << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n          ";
  for (std::size_t p = 0; p < n; ++p)
    out << p << (p + 1 < n ? " " : "");
  out << "\n        </DataArray>\n"
      << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n          ";
  for (std::size_t p = 0; p < n; ++p)
    out << p + 1 << (p + 1 < n ? " " : "");
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
  for (const auto &[time, file] : datasets)
    out << "    <DataSet timestep=\"" << exact(time) << "\" part=\"0\" file=\"" << file
        << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
}

} // namespace wash::detail
