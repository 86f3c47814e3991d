#include <wash/detail/writers.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
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

TEST(Writers, VtpHasPointsPaddedTo3DAndEveryColumn) {
  std::ostringstream out;
  writeVtp(sampleFrame(), out);
  const std::string s = out.str();
  EXPECT_NE(s.find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_NE(s.find("2 2.5 0 0 0.5 0 1 1.5 0"), std::string::npos); // z = 0 in 2D
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

TEST(Frame, FindsTheFirstNonFiniteValue) {
  Frame f = sampleFrame();
  EXPECT_EQ(findNonFinite(f), "");
  f.columns[3].values[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(findNonFinite(f), "field 'pressure' of particle 0 is nan");
}
