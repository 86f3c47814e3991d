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

} // namespace

std::string xmlText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const char *reference = c == '&'                  ? "&amp;"
                            : c == '<'                ? "&lt;"
                            : c == '>'                ? "&gt;"
                            : c == '"'                ? "&quot;"
                            : c == '\''               ? "&apos;"
                            : c == '\t'               ? "&#9;"
                            : c == '\n'               ? "&#10;"
                            : c == '\r'               ? "&#13;"
                            : (unsigned char)c < 0x20 ? "\xEF\xBF\xBD" // U+FFFD
                                                      : nullptr;
    if (reference)
      out += reference;
    else
      out += c;
  }
  return out;
}

std::string csvField(std::string_view field) {
  if (field.find_first_of(",\"\n\r") == std::string_view::npos)
    return std::string(field);
  std::string out = "\"";
  for (char c : field)
    out += c == '"' ? "\"\"" : std::string(1, c);
  return out + '"';
}

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

void writeCsvHeader(const Columns &columns, std::ostream &out) {
  out << "id";
  for (const Column *column : columns)
    for (const std::string &h : csvHeaders(*column))
      out << ',' << csvField(h);
  out << '\n';
}

void appendCsvRow(std::string &line, std::uint64_t id, const double *values, std::size_t width) {
  Text buf;
  line += std::to_string(id);
  for (std::size_t k = 0; k < width; ++k)
    (line += ',') += exact(values[k], buf);
  line += '\n';
}

void writeCsv(const Frame &frame, const Columns &columns, std::ostream &out) {
  writeCsvHeader(columns, out);
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

template <typename T> const char *vtkType();
template <> const char *vtkType<double>() { return "Float64"; }
template <> const char *vtkType<std::int64_t>() { return "Int64"; }

/// The opening tag of a DataArray, up to its format attributes.
template <typename T> void openArray(std::ostream &out, const std::string &name, int components) {
  out << "        <DataArray type=\"" << vtkType<T>() << "\" Name=\"" << xmlText(name) << "\"";
  if (components)
    out << " NumberOfComponents=\"" << components << "\"";
}

/// One array's values as text, single spaces between, given in pieces and
/// written a block at a time.
class TextValues {
public:
  explicit TextValues(std::ostream &out) : out_(out) {}
  template <typename T> void add(const T *values, std::size_t n) {
    Text buf;
    for (std::size_t k = 0; k < n; ++k) {
      if (!first_)
        block_ += ' ';
      first_ = false;
      if constexpr (std::is_same_v<T, double>)
        block_ += exact(values[k], buf);
      else
        block_ += written(buf, std::to_chars(buf, std::end(buf), values[k]));
      if (block_.size() >= 1 << 16) {
        out_ << block_;
        block_.clear();
      }
    }
  }
  ~TextValues() { out_ << block_; }

private:
  std::ostream &out_;
  std::string block_;
  bool first_ = true;
};

/// Connectivity (k) or offsets (k + 1) of the n vertex cells, a block at a time.
template <typename Emit> void cellNumbers(std::uint64_t n, std::int64_t shift, Emit emit) {
  std::vector<std::int64_t> block;
  for (std::uint64_t from = 0; from < n; from += 1 << 14) {
    block.clear();
    for (std::uint64_t k = from; k < std::min<std::uint64_t>(n, from + (1 << 14)); ++k)
      block.push_back(std::int64_t(k) + shift);
    emit(block.data(), block.size());
  }
}

} // namespace

std::vector<VtpArray> vtpArrays(const Frame &frame, const Columns &columns) {
  std::vector<VtpArray> arrays{{"Points", 3, nullptr, VtpArray::Points},
                               {"id", 1, nullptr, VtpArray::Id}};
  for (const Column *column : columns)
    if (column != &frame.columns.at(0))
      arrays.push_back({column->name, column->components, column, VtpArray::Values});
  return arrays;
}

void vtpArrayValues(const Frame &frame, const VtpArray &array, std::size_t begin, std::size_t end,
                    std::vector<double> &out) {
  switch (array.kind) {
  case VtpArray::Points: {
    const Column &pos = frame.columns.at(0);
    for (std::size_t p = begin; p < end; ++p)
      for (int c = 0; c < 3; ++c)
        out.push_back(c < pos.components ? pos.values[p * pos.components + c] : 0.0);
    return;
  }
  case VtpArray::Id:
    for (std::size_t p = begin; p < end; ++p)
      out.push_back(double(frame.ids[p]));
    return;
  case VtpArray::Values: {
    const std::vector<double> &v = array.column->values;
    const std::size_t c = std::size_t(array.components);
    out.insert(out.end(), v.begin() + std::ptrdiff_t(begin * c),
               v.begin() + std::ptrdiff_t(end * c));
    return;
  }
  }
}

void writeVtp(const Frame &frame, std::ostream &out, std::optional<double> time) {
  writeVtp(frame, frameColumns(frame, {}),
           VtpOptions{.ascii = true, .time = time, .typeNames = frame.typeNames}, out);
}

void writeVtp(const Frame &frame, const Columns &columns, const VtpOptions &options,
              std::ostream &out) {
  const std::vector<VtpArray> arrays = vtpArrays(frame, columns);
  std::vector<double> chunk;
  writeVtp(
      frame.size(), arrays, options,
      [&](std::size_t a, const VtpEmit &emit) {
        for (std::size_t from = 0; from < frame.size(); from += 1 << 14) {
          chunk.clear();
          vtpArrayValues(frame, arrays[a], from, std::min(frame.size(), from + (1 << 14)), chunk);
          emit(chunk.data(), chunk.size());
        }
      },
      out);
}

void writeVtp(std::uint64_t n, const std::vector<VtpArray> &arrays, const VtpOptions &options,
              const VtpFeed &feed, std::ostream &out) {
  static_assert(std::endian::native == std::endian::little, "binary VTK is written little-endian");
  const bool binary = !options.ascii;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"" << (binary ? "1.0" : "0.1")
      << "\" byte_order=\"LittleEndian\"" << (binary ? " header_type=\"UInt64\"" : "") << ">\n"
      << "  <PolyData>\n";
  if (options.time || !options.typeNames.empty()) {
    Text buf;
    out << "    <FieldData>\n";
    if (options.time)
      out << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
             "format=\"ascii\">"
          << exact(*options.time, buf) << "</DataArray>\n";
    // A typed simulation: type_<name> holds the index its "type" column uses.
    for (std::size_t t = 0; t < options.typeNames.size(); ++t)
      out << "      <DataArray type=\"Int64\" Name=\"type_" << xmlText(options.typeNames[t])
          << "\" NumberOfTuples=\"1\" format=\"ascii\">" << t << "</DataArray>\n";
    out << "    </FieldData>\n";
  }
  out << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n << "\">\n"
      << "      <Points>\n";
  // Binary: every array after the XML, in one appended block, each a UInt64
  // byte count then its bytes, at the offset its DataArray names.
  std::uint64_t offset = 0;
  auto appendedAt = [&](std::uint64_t values) {
    out << " format=\"appended\" offset=\"" << offset << "\"/>\n";
    offset += sizeof(std::uint64_t) + values * 8;
  };
  auto floats = [&](std::size_t a) {
    openArray<double>(out, arrays[a].name, arrays[a].components);
    if (binary)
      return appendedAt(n * std::uint64_t(arrays[a].components));
    out << " format=\"ascii\">\n          ";
    {
      TextValues text(out);
      feed(a, [&](const double *v, std::size_t k) { text.add(v, k); });
    }
    out << "\n        </DataArray>\n";
  };
  auto cells = [&](const char *name, std::int64_t shift) {
    openArray<std::int64_t>(out, name, 0);
    if (binary)
      return appendedAt(n);
    out << " format=\"ascii\">\n          ";
    {
      TextValues text(out);
      cellNumbers(n, shift, [&](const std::int64_t *v, std::size_t k) { text.add(v, k); });
    }
    out << "\n        </DataArray>\n";
  };
  floats(0);
  out << "      </Points>\n      <Verts>\n";
  cells("connectivity", 0);
  cells("offsets", 1);
  out << "      </Verts>\n      <PointData>\n";
  for (std::size_t a = 1; a < arrays.size(); ++a)
    floats(a);
  out << "      </PointData>\n    </Piece>\n  </PolyData>\n";
  if (binary) {
    out << "  <AppendedData encoding=\"raw\">\n   _";
    auto count = [&](std::uint64_t values) {
      const std::uint64_t bytes = values * 8;
      out.write(reinterpret_cast<const char *>(&bytes), sizeof bytes);
    };
    auto raw = [&](const auto *v, std::size_t k) {
      out.write(reinterpret_cast<const char *>(v), std::streamsize(k * sizeof *v));
    };
    auto values = [&](std::size_t a) {
      count(n * std::uint64_t(arrays[a].components));
      feed(a, [&](const double *v, std::size_t k) { raw(v, k); });
    };
    values(0);
    for (std::int64_t shift : {0, 1}) {
      count(n);
      cellNumbers(n, shift, [&](const std::int64_t *v, std::size_t k) { raw(v, k); });
    }
    for (std::size_t a = 1; a < arrays.size(); ++a)
      values(a);
    out << "\n  </AppendedData>\n";
  }
  out << "</VTKFile>\n";
}

void writePvd(const std::vector<std::pair<double, std::string>> &datasets, std::ostream &out) {
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  Text buf;
  for (const auto &[time, file] : datasets)
    out << "    <DataSet timestep=\"" << exact(time, buf) << "\" part=\"0\" file=\""
        << xmlText(file) << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
}

} // namespace wash::detail
