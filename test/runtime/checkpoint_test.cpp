#include <wash/detail/checkpoint.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace wash::detail;
namespace fs = std::filesystem;

namespace {

CheckpointIdentity identity() {
  return {"sim", identityHash("kernels: a"), 2, false, {{"id", 8}, {"density", 8}}};
}

Shard shardOf(std::uint64_t n) {
  Shard s;
  s.particles = n;
  for (const CheckpointField &f : identity().fields) {
    Shard::Column c{f, std::vector<char>(n * f.elementBytes)};
    for (std::size_t k = 0; k < c.bytes.size(); ++k)
      c.bytes[k] = char(k * 7 + f.elementBytes);
    s.columns.push_back(c);
  }
  return s;
}

struct Checkpoint : testing::Test {
  fs::path dir = fs::temp_directory_path() / ("wash_ckpt_test_" + std::to_string(::getpid()));
  std::string folder;
  void SetUp() override {
    fs::remove_all(dir);
    folder = checkpointFolder(dir.string(), 7);
    const std::string partial = partialFolder(folder);
    beginCheckpoint(partial);
    CheckpointState s;
    s.shardChecksums = {writeShard(shardPath(partial, 0), identity(), shardOf(5))};
    s.iteration = 7;
    s.time = 0.25;
    s.variables = {{"speed", 1.5}};
    s.frames = {{5, 0.2, "sim_000005.vtp"}};
    s.particles = 5;
    writeIndex(indexPath(partial), identity(), s);
    completeCheckpoint(partial, folder, 2);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string refusal(std::uint32_t shard, const CheckpointIdentity &id) {
    try {
      readShard(folder, shard, id, readIndex(folder, identity()));
    } catch (const RunError &e) {
      return e.what();
    }
    return "";
  }
};

} // namespace

TEST_F(Checkpoint, RoundTrip) {
  EXPECT_EQ(resolveRestart(dir.string()), folder);
  const CheckpointState s = readIndex(folder, identity());
  EXPECT_EQ(s.iteration, 7u);
  EXPECT_EQ(s.time, 0.25);
  ASSERT_EQ(s.variables.size(), 1u);
  EXPECT_EQ(s.variables[0].second, 1.5);
  ASSERT_EQ(s.frames.size(), 1u);
  EXPECT_EQ(s.frames[0].file, "sim_000005.vtp");
  const Shard read = readShard(folder, 0, identity(), s);
  const Shard written = shardOf(5);
  ASSERT_EQ(read.columns.size(), written.columns.size());
  for (std::size_t c = 0; c < read.columns.size(); ++c)
    EXPECT_EQ(read.columns[c].bytes, written.columns[c].bytes);
}

TEST_F(Checkpoint, TruncatedAndCorruptedAreRefused) {
  const std::string shard = shardPath(folder, 0);
  const auto size = fs::file_size(shard);
  fs::resize_file(shard, size - 3);
  EXPECT_NE(refusal(0, identity()).find("is truncated"), std::string::npos);
  fs::resize_file(shard, size);
  // The three bytes back are zeros: the checksum no longer matches.
  EXPECT_NE(refusal(0, identity()).find("is corrupted"), std::string::npos);
  fs::resize_file(indexPath(folder), fs::file_size(indexPath(folder)) - 30);
  try {
    readIndex(folder, identity());
    ADD_FAILURE() << "a truncated index was read";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
}

TEST_F(Checkpoint, AnotherProgramIsRefused) {
  CheckpointIdentity other = identity();
  other.useFloat = true;
  EXPECT_NE(refusal(0, other).find("holds double-precision state"), std::string::npos);
  other = identity();
  other.simulation = "else";
  EXPECT_NE(refusal(0, other).find("of simulation 'sim'"), std::string::npos);
  other = identity();
  other.fields.pop_back();
  try {
    readIndex(folder, other);
    ADD_FAILURE() << "columns not checked";
  } catch (const RunError &e) {
    EXPECT_NE(std::string(e.what()).find("its columns are"), std::string::npos) << e.what();
  }
}

TEST_F(Checkpoint, OnlyTheNewestAreKept) {
  for (std::uint64_t it : {9, 11}) {
    const std::string f = checkpointFolder(dir.string(), it), partial = partialFolder(f);
    beginCheckpoint(partial);
    CheckpointState s;
    s.shardChecksums = {writeShard(shardPath(partial, 0), identity(), shardOf(1))};
    s.iteration = it;
    writeIndex(indexPath(partial), identity(), s);
    completeCheckpoint(partial, f, 2);
  }
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_TRUE(fs::exists(checkpointFolder(dir.string(), 9)));
  fs::create_directories(partialFolder(checkpointFolder(dir.string(), 12))); // incomplete
  EXPECT_EQ(resolveRestart(dir.string()), checkpointFolder(dir.string(), 11));
}

TEST_F(Checkpoint, AShardOfAnotherCheckpointIsRefused) {
  const std::string other = checkpointFolder(dir.string(), 9), partial = partialFolder(other);
  beginCheckpoint(partial);
  CheckpointState s;
  s.iteration = 9;
  s.particles = 4;
  s.shardChecksums = {writeShard(shardPath(partial, 0), identity(), shardOf(4))};
  writeIndex(indexPath(partial), identity(), s);
  completeCheckpoint(partial, other, 2);
  fs::copy_file(shardPath(other, 0), shardPath(folder, 0), fs::copy_options::overwrite_existing);
  EXPECT_NE(refusal(0, identity()).find("is not the one its index was written with"),
            std::string::npos);
}

TEST_F(Checkpoint, AnIndexWithoutItsShardsChecksumsIsNotWritten) {
  CheckpointState s;
  s.shards = 2;
  s.shardChecksums = {1};
  EXPECT_THROW(writeIndex((dir / "index.wck").string(), identity(), s), RunError);
}
