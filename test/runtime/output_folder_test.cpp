#include <wash/detail/output_folder.hpp>
#include <wash/detail/run_output.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

using namespace wash::detail;
namespace fs = std::filesystem;

namespace {

struct OutputFolder : testing::Test {
  fs::path dir =
      fs::temp_directory_path() / ("wash-folder-test-" + std::to_string(::getpid()) + "-" +
                                   testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
};

} // namespace

// flock locks of two opens conflict even in one process: the second lock
// stands for a second run.
TEST_F(OutputFolder, ASecondLockIsRefusedNamingTheFirst) {
  std::string message;
  {
    FolderLock first(dir.string(), "output directory", "--out");
    try {
      FolderLock second(dir.string(), "output directory", "--out");
    } catch (const RunError &e) {
      message = e.what();
    }
    EXPECT_TRUE(fs::exists(dir / ".wash-lock"));
  }
  EXPECT_NE(message.find("output directory '" + dir.string() + "' is in use by another run: pid " +
                         std::to_string(::getpid()) + " on host "),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("give this one another --out"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(dir / ".wash-lock")); // removed as the lock is released
  EXPECT_NO_THROW(FolderLock(dir.string(), "output directory", "--out"));
}

TEST_F(OutputFolder, ALeftoverLockFileRefusesNobody) {
  std::ofstream(dir / ".wash-lock") << "pid 1 on host gone, started long ago (killed)\n";
  EXPECT_NO_THROW(FolderLock(dir.string(), "output directory", "--out"));
}

TEST_F(OutputFolder, PartialNamesAreTheWritersOwn) {
  EXPECT_EQ(partialPath("out/a.vtp", 42), "out/a.vtp.wash-partial.42");
  EXPECT_EQ(partialPath("a.csv"), "a.csv.wash-partial." + std::to_string(::getpid()));
}

TEST_F(OutputFolder, OnlyDeadProcessesPartialsAreRemoved) {
  const std::string live = partialPath((dir / "a.vtp").string());
  const std::string dead = partialPath((dir / "b.vtp").string(), 999999999); // above pid_max
  const std::string other = (dir / "c.vtp.wash-partial.x").string();
  for (const std::string &f : {live, dead, other})
    std::ofstream(f) << "x";
  removeStalePartials(dir.string());
  EXPECT_TRUE(fs::exists(live));
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(other));
}

TEST_F(OutputFolder, AFolderThatCannotBeCreatedIsAClearError) {
  std::ofstream(dir / "file") << "x";
  const std::string bad = (dir / "file" / "sub").string();
  try {
    checkWritableFolder(bad, "checkpoint directory");
    ADD_FAILURE() << "a folder under a file was accepted";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("cannot create checkpoint directory '" + bad + "'"),
              std::string::npos)
        << e.what();
  }
  checkWritableFolder((dir / "new" / "ck").string(), "checkpoint directory");
  EXPECT_TRUE(fs::is_directory(dir / "new" / "ck"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "new" / "ck"), fs::directory_iterator()), 0);
}
