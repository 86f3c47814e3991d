#include <wash/detail/run_output.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace wash::detail;
namespace fs = std::filesystem;

namespace {

struct TempDir {
  fs::path path = fs::temp_directory_path() /
                  ("wash-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                   "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::remove_all(path); }
  ~TempDir() { fs::remove_all(path); }
};

Frame tinyFrame() {
  Frame f;
  f.ids = {0};
  f.columns.push_back({"pos", 2, {1.0, 2.0}});
  return f;
}

std::string slurp(const fs::path &p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

} // namespace

TEST(RunOutput, FinalStateOnlyByDefault) {
  TempDir dir;
  RunOptions o;
  o.outDir = (dir.path / "nested" / "out").string();
  RunOutput out(o, "sim");
  EXPECT_TRUE(fs::is_directory(o.outDir)); // created, nested
  EXPECT_FALSE(out.frameDue(0, 10));
  EXPECT_FALSE(out.frameDue(5, 10));
  EXPECT_TRUE(out.frameDue(10, 10));
}

TEST(RunOutput, EveryKStepsPlusFirstAndLast) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  o.outputEvery = 4;
  RunOutput out(o, "sim");
  std::vector<std::uint64_t> due;
  for (std::uint64_t s = 0; s <= 10; ++s)
    if (out.frameDue(s, 10))
      due.push_back(s);
  EXPECT_EQ(due, (std::vector<std::uint64_t>{0, 4, 8, 10}));
}

TEST(RunOutput, WritesFramesSeriesAndDump) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  o.dumpPath = (dir.path / "dump.csv").string();
  RunOutput out(o, "sim");
  out.writeFrame(0, tinyFrame());
  out.writeFrame(7, tinyFrame());
  out.finish(tinyFrame());
  EXPECT_TRUE(fs::exists(dir.path / "sim_000000.vtp"));
  EXPECT_TRUE(fs::exists(dir.path / "sim_000007.vtp"));
  EXPECT_NE(slurp(dir.path / "sim.pvd").find("sim_000007.vtp"), std::string::npos);
  EXPECT_EQ(slurp(dir.path / "dump.csv"), "id,x,y\n0,1,2\n");
}

TEST(RunOutput, TheSeriesIsOnDiskAfterEveryFrame) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  {
    RunOutput out(o, "sim");
    out.writeFrame(0, tinyFrame());
    EXPECT_NE(slurp(dir.path / "sim.pvd").find("sim_000000.vtp"), std::string::npos);
    out.writeFrame(5, tinyFrame());
    EXPECT_NE(slurp(dir.path / "sim.pvd").find("sim_000005.vtp"), std::string::npos);
  } // the run ends (and leaves the folder) before the restart takes it
  // A restart from a checkpoint after step 0 lists only frame 0 until it writes.
  RunOutput restarted(o, "sim");
  restarted.continueSeries({{0, 0.0, "sim_000000.vtp"}}, false);
  EXPECT_EQ(slurp(dir.path / "sim.pvd").find("sim_000005.vtp"), std::string::npos);
  EXPECT_NE(slurp(dir.path / "sim.pvd").find("sim_000000.vtp"), std::string::npos);
}

TEST(RunOutput, CsvFormatWritesCsvFrames) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  o.format = OutputFormat::Csv;
  RunOutput out(o, "sim");
  out.writeFrame(3, tinyFrame());
  out.finish(tinyFrame());
  EXPECT_EQ(slurp(dir.path / "sim_000003.csv"), "id,x,y\n0,1,2\n");
  EXPECT_FALSE(fs::exists(dir.path / "sim.pvd"));
}

TEST(RunOutput, UnusableDirectoryIsAClearError) {
  TempDir dir;
  fs::create_directories(dir.path);
  std::ofstream(dir.path / "file") << "x";
  RunOptions o;
  o.outDir = (dir.path / "file" / "sub").string();
  try {
    RunOutput out(o, "sim");
    FAIL() << "no error";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("cannot create output directory"), std::string::npos);
  }
}

TEST(RunOutput, NamesWithASlashAreRefused) {
  EXPECT_EQ(checkOutputName("sim"), "");
  EXPECT_EQ(checkOutputName(".."), ""); // "out/.._000001.vtp" is still inside
  for (const char *name : {"../x", "/abs/x", "sub/x"})
    EXPECT_NE(checkOutputName(name).find("is not a plain file name"), std::string::npos) << name;
  EXPECT_EQ(checkOutputName("a&<b>\"c'\n,d"), ""); // escaped where written
  EXPECT_NE(checkOutputName("a\x01"), "");
  TempDir dir;
  RunOptions o;
  o.outDir = (dir.path / "out").string();
  EXPECT_THROW(RunOutput(o, "../escaped"), RunError);
}

TEST(RunOutput, WritesLeaveNoPartialFiles) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  o.dumpPath = (dir.path / "dump.csv").string();
  {
    RunOutput out(o, "sim");
    out.reserve(1 << 20);
    out.writeFrame(0, tinyFrame());
    out.finish(tinyFrame());
    EXPECT_TRUE(fs::exists(dir.path / ".wash-lock")); // while the run lasts
  }
  std::vector<std::string> names;
  for (const auto &entry : fs::directory_iterator(dir.path))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"dump.csv", "sim.pvd", "sim_000000.vtp"}));
}

TEST(RunOutput, UnusableDumpPathIsFoundAtStartUp) {
  TempDir dir;
  RunOptions o;
  o.outDir = dir.path.string();
  o.dumpPath = (dir.path / "missing" / "dump.csv").string();
  try {
    RunOutput out(o, "sim");
    FAIL() << "no error";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("cannot write the dump to"), std::string::npos);
  }
}

TEST(RunOutput, FailedWriteSaysWhy) {
  try {
    writeCsvFile(tinyFrame(), "/dev/full");
    FAIL() << "no error";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
}
