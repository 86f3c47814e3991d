#include <wash/detail/writers.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>

using namespace wash::detail;

namespace {

Frame sampleFrame() {
  Frame f;
  f.dimensions = 2;
  f.ids = {2, 0, 1};
  f.columns.push_back({"pos", 2, {2.0, 2.5, 0.0, 0.5, 1.0, 1.5}});
  f.columns.push_back({"vel", 2, {0.0, 0.0, 0.1, 0.2, 0.0, 0.0}});
  f.columns.push_back({"density", 1, {3.0, 1.0 / 3.0, 2.0}});
  f.columns.push_back({"pressure", 2, {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}});
  return f;
}

} // namespace

TEST(Writers, CsvHasHeaderAndRowsSortedByIdWithExactValues) {
  std::ostringstream out;
  writeCsv(sampleFrame(), out);
  EXPECT_EQ(out.str(), "id,x,y,vx,vy,density,pressure_x,pressure_y\n"
                       "0,0,0.5,0.10000000000000001,0.20000000000000001,0.33333333333333331,3,4\n"
                       "1,1,1.5,0,0,2,5,6\n"
                       "2,2,2.5,0,0,3,1,2\n");
}

TEST(Writers, CsvValuesReadBackAsTheSameDoubles) {
  Frame f = sampleFrame();
  f.columns[2].values = {1e-300, 0.1 + 0.2, -123456.789012345678};
  std::ostringstream out;
  writeCsv(f, out);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line); // header
  for (std::size_t row : f.orderById()) {
    std::getline(in, line);
    std::istringstream cells(line);
    std::string cell;
    for (int k = 0; k < 6; ++k)
      std::getline(cells, cell, ',');
    EXPECT_EQ(std::strtod(cell.c_str(), nullptr), f.columns[2].values[row]);
  }
}

// docs/semantics.md promises printf's %.17g, digit for digit: users diff and
// parse these files.
TEST(Writers, ValuesAreWrittenAsPrintfWrites17SignificantDigits) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0 / 3.0,
                                1e-300,
                                5e-324,
                                1e22,
                                1e21,
                                123456789.0,
                                -2.5e-7,
                                1e17,
                                0.1 + 0.2,
                                std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
  std::uint64_t bits = 0x9E3779B97F4A7C15u;
  for (int k = 0; k < 2000; ++k) { // random bit patterns, every exponent
    bits ^= bits << 13, bits ^= bits >> 7, bits ^= bits << 17;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    values.push_back(v);
  }
  Frame f;
  f.dimensions = 2;
  f.columns = {{"pos", 2, {}}, {"density", 1, values}};
  for (std::size_t k = 0; k < values.size(); ++k) {
    f.ids.push_back(k);
    f.columns[0].values.insert(f.columns[0].values.end(), {0.0, 0.0});
  }
  std::ostringstream csv, vtp;
  writeCsv(f, csv);
  writeVtp(f, vtp);
  std::string csvRows = "id,x,y,density\n", vtpArray;
  char text[64];
  for (std::size_t k = 0; k < values.size(); ++k) {
    std::snprintf(text, sizeof text, "%.17g", values[k]);
    csvRows += std::to_string(k) + ",0,0," + text + "\n";
    vtpArray += (k ? " " : "") + std::string(text);
  }
  EXPECT_EQ(csv.str(), csvRows);
  EXPECT_NE(vtp.str().find("format=\"ascii\">\n          " + vtpArray + "\n"), std::string::npos);
}

TEST(Writers, VtpHasPointsPaddedTo3DAndEveryColumn) {
  std::ostringstream out;
  writeVtp(sampleFrame(), out);
  const std::string s = out.str();
  EXPECT_NE(s.find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(s.find("2 2.5 0 0 0.5 0 1 1.5 0"), std::string::npos); // z = 0 in 2D
  // One vertex cell per point: cell k is point k and ends at offset k + 1.
  EXPECT_NE(s.find("Name=\"connectivity\" format=\"ascii\">\n          0 1 2\n"),
            std::string::npos);
  EXPECT_NE(s.find("Name=\"offsets\" format=\"ascii\">\n          1 2 3\n"), std::string::npos);
  for (const char *name : {"Name=\"id\"", "Name=\"vel\"", "Name=\"density\"", "Name=\"pressure\""})
    EXPECT_NE(s.find(name), std::string::npos) << name;
  EXPECT_NE(s.find("</VTKFile>"), std::string::npos);
}

TEST(Writers, PvdListsEveryDataset) {
  std::ostringstream out;
  writePvd({{0.0, "a_000000.vtp"}, {10.0, "a_000010.vtp"}}, out);
  EXPECT_NE(out.str().find("timestep=\"0\" part=\"0\" file=\"a_000000.vtp\""), std::string::npos);
  EXPECT_NE(out.str().find("timestep=\"10\" part=\"0\" file=\"a_000010.vtp\""), std::string::npos);
}

TEST(Writers, NamesAreEscapedInXmlAndQuotedInCsv) {
  EXPECT_EQ(xmlText("a&b<c>d\"e'f\tg\nh"), "a&amp;b&lt;c&gt;d&quot;e&apos;f&#9;g&#10;h");
  EXPECT_EQ(xmlText(std::string("x\x01y")), "x\xEF\xBF\xBDy");
  EXPECT_EQ(csvField("plain name"), "plain name");
  EXPECT_EQ(csvField("a,b\"c\nd"), "\"a,b\"\"c\nd\"");
  std::ostringstream pvd;
  writePvd({{0.0, "a&<b>\"_000000.vtp"}}, pvd);
  EXPECT_NE(pvd.str().find("file=\"a&amp;&lt;b&gt;&quot;_000000.vtp\""), std::string::npos);
  Frame f = sampleFrame();
  f.columns[2].name = "d,\"<n>";
  std::ostringstream csv, vtp;
  writeCsv(f, csv);
  EXPECT_EQ(csv.str().substr(0, csv.str().find('\n')),
            "id,x,y,vx,vy,\"d,\"\"<n>\",pressure_x,pressure_y");
  writeVtp(f, vtp);
  EXPECT_NE(vtp.str().find("Name=\"d,&quot;&lt;n&gt;\""), std::string::npos);
}

TEST(Frame, FindsTheFirstNonFiniteValue) {
  Frame f = sampleFrame();
  EXPECT_EQ(findNonFinite(f), "");
  f.columns[3].values[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(findNonFinite(f), "field 'pressure' of particle 0 is nan");
}

TEST(Writers, FrameOnlyColumnsAreNeverInTheDumpAndFieldsChooseFrameColumns) {
  Frame f = sampleFrame();
  f.columns.insert(f.columns.begin() + 2, Column{"acc", 2, {1.0, 1.0, 2.0, 2.0, 3.0, 3.0}, false});
  std::ostringstream dump, frame;
  writeCsv(f, dump);
  EXPECT_EQ(dump.str().substr(0, dump.str().find('\n')),
            "id,x,y,vx,vy,density,pressure_x,pressure_y");
  std::vector<std::string> unknown;
  writeCsv(f, frameColumns(f, {"pressure", "acc", "nope"}, &unknown), frame);
  EXPECT_EQ(frame.str().substr(0, frame.str().find('\n')),
            "id,x,y,acc_x,acc_y,pressure_x,pressure_y");
  EXPECT_EQ(unknown, std::vector<std::string>{"nope"});
}

TEST(Writers, BinaryVtpAppendsEveryArrayRaw) {
  std::ostringstream out;
  Frame f = sampleFrame();
  writeVtp(f, frameColumns(f, {}), VtpOptions{.ascii = false, .time = 0.25}, out);
  const std::string s = out.str();
  EXPECT_EQ(s.find("format=\"ascii\">\n"), std::string::npos);
  EXPECT_NE(s.find("Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">0.25</DataArray>"),
            std::string::npos);
  // Points, connectivity, offsets, id, vel, density, pressure: a UInt64 count then the bytes.
  const std::size_t data = s.find("<AppendedData encoding=\"raw\">\n   _") + 34;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, s.data() + data, sizeof bytes);
  EXPECT_EQ(bytes, 9 * sizeof(double)); // the points, padded to 3D
  double z1 = 1.0;
  std::memcpy(&z1, s.data() + data + 8 + 5 * sizeof(double), sizeof z1);
  EXPECT_EQ(z1, 0.0);
  EXPECT_NE(s.find("Name=\"pressure\" NumberOfComponents=\"2\" format=\"appended\" offset=\""),
            std::string::npos);
}
