#include <wash/detail/options.hpp>

#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

using namespace wash::detail;

namespace {

ParsedArgs parse(std::initializer_list<const char *> args) {
  static std::vector<std::string> storage;
  storage.assign(args.begin(), args.end());
  static std::vector<char *> argv;
  argv.clear();
  for (auto &s : storage)
    argv.push_back(s.data());
  return parseProgramOptions(int(argv.size()), argv.data());
}

std::vector<std::string> userArgs(const ParsedArgs &p) {
  std::vector<std::string> out;
  for (char *a : p.userArgv)
    if (a)
      out.push_back(a);
  return out;
}

} // namespace

TEST(Options, DefaultsWhenNoneGiven) {
  auto p = parse({"sim"});
  EXPECT_FALSE(p.options.steps.has_value());
  EXPECT_EQ(p.options.outDir, "out");
  EXPECT_EQ(p.options.outputEvery, 0u);
  EXPECT_EQ(p.options.format, OutputFormat::Vtk);
  EXPECT_TRUE(p.options.dumpPath.empty());
  EXPECT_FALSE(p.options.quiet);
  EXPECT_EQ(userArgs(p), std::vector<std::string>{"sim"});
  EXPECT_EQ(p.userArgv.back(), nullptr);
}

TEST(Options, WashOptionsAreRemovedAndTheRestKeptInOrder) {
  auto p = parse({"sim", "name", "--steps", "12", "--out=o", "--format", "csv", "file",
                  "--output-every=5", "--dump", "d.csv", "--quiet"});
  EXPECT_EQ(*p.options.steps, 12u);
  EXPECT_EQ(p.options.outDir, "o");
  EXPECT_EQ(p.options.format, OutputFormat::Csv);
  EXPECT_EQ(p.options.outputEvery, 5u);
  EXPECT_EQ(p.options.dumpPath, "d.csv");
  EXPECT_TRUE(p.options.quiet);
  EXPECT_EQ(userArgs(p), (std::vector<std::string>{"sim", "name", "file"}));
}

TEST(Options, DoubleDashPassesEverythingThrough) {
  auto p = parse({"sim", "--steps", "3", "--", "--steps", "x"});
  EXPECT_EQ(*p.options.steps, 3u);
  EXPECT_EQ(userArgs(p), (std::vector<std::string>{"sim", "--steps", "x"}));
}

TEST(Options, HelpIsRecognised) {
  EXPECT_TRUE(parse({"sim", "--help"}).options.help);
  EXPECT_NE(usageText("sim").find("--output-every"), std::string::npos);
}

TEST(Options, BadInputIsRejectedWithAMessage) {
  auto expectError = [](std::initializer_list<const char *> args, const std::string &needle) {
    try {
      parse(args);
      ADD_FAILURE() << "no error for " << needle;
    } catch (const OptionError &e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expectError({"sim", "--steps"}, "expects a value");
  expectError({"sim", "--steps", "-3"}, "non-negative integer");
  expectError({"sim", "--steps=12x"}, "non-negative integer");
  expectError({"sim", "--format", "png"}, "'vtk', 'csv' or 'hdf5'");
  expectError({"sim", "--frobnicate"}, "unknown option '--frobnicate'");
  expectError({"sim", "--quiet=yes"}, "takes no value");
  expectError({"sim", "--dump="}, "expects a path");
  expectError({"sim", "--keep-checkpoints", "0"}, "at least 1");
  expectError({"sim", "--checkpoint-dt", "0"}, "positive simulated time");
  expectError({"sim", "--restart="}, "expects a path");
  expectError({"sim", "--steps", "18446744073709551616"}, "non-negative integer");
  expectError({"sim", "--end-time", "1e400"}, "non-negative simulated time");
  for (const char *bad : {"-1", "nan", "inf", "1e400", "3s"})
    expectError({"sim", "--watchdog", bad}, "expects a non-negative number of seconds (0: off)");
}

TEST(Options, Watchdog) {
  EXPECT_FALSE(parse({"sim"}).options.watchdog.has_value());
  EXPECT_EQ(parse({"sim", "--watchdog", "0"}).options.watchdog, 0.0);
  EXPECT_EQ(parse({"sim", "--watchdog=2.5"}).options.watchdog, 2.5);
}

TEST(Options, CheckpointOptions) {
  auto p = parse({"sim", "--checkpoint-every", "5", "--checkpoint-dt=0.5", "--checkpoint-dir", "c",
                  "--keep-checkpoints", "3", "--restart", "c/checkpoint_000005"});
  EXPECT_EQ(p.options.checkpointEvery, 5u);
  EXPECT_EQ(p.options.checkpointDt, 0.5);
  EXPECT_EQ(p.options.checkpointDir, "c");
  EXPECT_EQ(p.options.keepCheckpoints, 3u);
  EXPECT_EQ(p.options.restartPath, "c/checkpoint_000005");
  EXPECT_EQ(parse({"sim"}).options.keepCheckpoints, 2u);
}
