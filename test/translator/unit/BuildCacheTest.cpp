//===- BuildCacheTest.cpp - wash run's cache ------------------------------===//
#include "wash/translator/Run/BuildCache.h"
#include "wash/translator/Emit/ProjectManifest.h"

#include "llvm/ADT/SmallString.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace wash::tr {
namespace {

namespace fs = llvm::sys::fs;

/// A fresh folder, removed after the test.
class BuildCacheTest : public ::testing::Test {
protected:
  void SetUp() override {
    ASSERT_FALSE(fs::createUniqueDirectory("wash-cache-test", Dir));
    Entry = path("entry");
    Header = path("scene.hpp");
    write(Header, "constexpr double Speed = 0.5;\n");
  }
  void TearDown() override { fs::remove_directories(Dir); }

  std::string path(llvm::StringRef Name) const {
    llvm::SmallString<256> P(Dir);
    llvm::sys::path::append(P, Name);
    return std::string(P);
  }
  static void write(const std::string &Path, llvm::StringRef Text) {
    std::error_code EC;
    llvm::raw_fd_ostream OS(Path, EC);
    ASSERT_FALSE(EC);
    OS << Text;
  }
  /// Header as the translation read it now.
  InputFile input() const { return {Header, contentHash("constexpr double Speed = 0.5;\n")}; }

  llvm::SmallString<256> Dir;
  std::string Entry, Header;
};

TEST_F(BuildCacheTest, CurrentWhileEveryInputHoldsWhatItHeld) {
  EXPECT_FALSE(buildIsCurrent(Entry, "serial")) << "no record yet";
  ASSERT_TRUE(fs::create_directories(Entry) == std::error_code());
  ASSERT_EQ(recordBuild(Entry, "serial", {input()}), "");
  EXPECT_TRUE(buildIsCurrent(Entry, "serial"));
  EXPECT_FALSE(buildIsCurrent(Entry, "openmp")) << "another configuration";

  // The same content, written again (a touch): still current.
  write(Header, "constexpr double Speed = 0.5;\n");
  EXPECT_TRUE(buildIsCurrent(Entry, "serial"));
  write(Header, "constexpr double Speed = 0.7;\n");
  EXPECT_FALSE(buildIsCurrent(Entry, "serial"));
  write(Header, "constexpr double Speed = 0.5;\n");
  fs::remove(Header);
  EXPECT_FALSE(buildIsCurrent(Entry, "serial")) << "an input gone";
}

TEST_F(BuildCacheTest, ForgottenOrUnrecordableBuildsAreNotCurrent) {
  ASSERT_TRUE(fs::create_directories(Entry) == std::error_code());
  ASSERT_EQ(recordBuild(Entry, "serial", {input()}), "");
  ASSERT_EQ(forgetBuild(Entry), "");
  EXPECT_FALSE(buildIsCurrent(Entry, "serial"));
  // An input the translation could not hash: no record, so rebuilt.
  ASSERT_EQ(recordBuild(Entry, "serial", {input()}), "");
  ASSERT_EQ(recordBuild(Entry, "serial", {input(), {path("other.hpp"), ""}}), "");
  EXPECT_FALSE(buildIsCurrent(Entry, "serial"));
}

TEST_F(BuildCacheTest, EntryNamesSayWhatAndDifferByConfiguration) {
  std::string Serial = entryName("/home/u/my sim.cpp", "serial", "compiler /usr/bin/g++");
  EXPECT_EQ(Serial.substr(0, 14), "my_sim-serial-");
  EXPECT_EQ(Serial.size(), 14u + 16u);
  EXPECT_EQ(Serial, entryName("/home/u/my sim.cpp", "serial", "compiler /usr/bin/g++"));
  EXPECT_NE(Serial, entryName("/home/u/my sim.cpp", "serial", "compiler /usr/bin/clang++"));
  EXPECT_NE(Serial, entryName("/home/v/my sim.cpp", "serial", "compiler /usr/bin/g++"));
}

TEST_F(BuildCacheTest, CacheFollowsXdg) {
  std::string Error;
  ::setenv("XDG_CACHE_HOME", Dir.c_str(), 1);
  EXPECT_EQ(cacheRoot(Error), path("wash"));
  // Relative: ignored, as the XDG specification says.
  ::setenv("XDG_CACHE_HOME", "relative", 1);
  ::setenv("HOME", Dir.c_str(), 1);
  EXPECT_EQ(cacheRoot(Error), path(".cache/wash"));
  ::unsetenv("XDG_CACHE_HOME");
  EXPECT_EQ(cacheRoot(Error), path(".cache/wash"));

  ::setenv("XDG_CACHE_HOME", Dir.c_str(), 1);
  ASSERT_TRUE(fs::create_directories(path("wash/sim-serial-0/build")) == std::error_code());
  EXPECT_EQ(cleanCache(), "");
  EXPECT_FALSE(fs::exists(path("wash")));
  EXPECT_EQ(cleanCache(), "") << "nothing to clean is no error";
}

TEST_F(BuildCacheTest, EntryLockCreatesTheEntry) {
  std::string Error;
  {
    EntryLock Lock(Entry, Error);
    EXPECT_EQ(Error, "");
    EXPECT_TRUE(fs::exists(path("entry/lock")));
  }
  // Released: it can be taken again.
  EntryLock Again(Entry, Error);
  EXPECT_EQ(Error, "");
}

} // namespace
} // namespace wash::tr
