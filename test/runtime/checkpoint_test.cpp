#include <wash/detail/checkpoint.hpp>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace wash::detail;
namespace fs = std::filesystem;

namespace {

CheckpointIdentity identity() {
  return {"sim", identityHash("kernels: a"),  2,
          false, {{"id", 8}, {"density", 8}}, CheckpointWriter::Translated};
}

/// Rewrites a version 3 file as version 2 wrote it: no writer byte after the
/// program hash (the identity's second string), its checksum recomputed; an
/// index's last word, its one shard's checksum, replaced by `shardSum`.
/// Returns the new checksum.
std::uint64_t downgradeToVersion2(const std::string &path,
                                  const std::uint64_t *shardSum = nullptr) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  in.close();
  std::size_t at = 12; // magic, version
  for (int text = 0; text < 2; ++text) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + at, 4);
    at += 4 + n;
  }
  bytes.erase(at, 1);
  bytes[8] = 2;
  bytes.resize(bytes.size() - 8);
  if (shardSum)
    std::memcpy(bytes.data() + bytes.size() - 8, shardSum, 8);
  const std::uint64_t sum = checkpointChecksum(bytes.data(), bytes.size());
  bytes.append(reinterpret_cast<const char *>(&sum), 8);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return sum;
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

std::string indexRefusal(const std::string &folder, const CheckpointIdentity &want) {
  try {
    readIndex(folder, want);
  } catch (const RunError &e) {
    return e.what();
  }
  return "";
}

TEST_F(Checkpoint, TheWriterIsNamedWhenAReferenceAndATranslatedProgramMeet) {
  CheckpointIdentity reference = identity();
  reference.program = identityHash("reference kernels: a");
  reference.writer = CheckpointWriter::Reference;
  EXPECT_NE(indexRefusal(folder, reference)
                .find("it was written by a translated program; a reference build restarts only "
                      "from its own checkpoints"),
            std::string::npos)
      << indexRefusal(folder, reference);
  EXPECT_NE(refusal(0, reference).find("written by a translated program"), std::string::npos);
  CheckpointIdentity translated = identity();
  translated.program = identityHash("kernels: b");
  EXPECT_NE(indexRefusal(folder, translated)
                .find("it was written by another program (kernels or "
                      "columns differ"),
            std::string::npos)
      << indexRefusal(folder, translated);

  // And the reverse: a reference checkpoint read by a translated program.
  const std::string other = checkpointFolder(dir.string(), 9), partial = partialFolder(other);
  beginCheckpoint(partial);
  CheckpointState s;
  s.shardChecksums = {writeShard(shardPath(partial, 0), reference, shardOf(1))};
  writeIndex(indexPath(partial), reference, s);
  completeCheckpoint(partial, other, 2);
  EXPECT_NE(indexRefusal(other, identity()).find("it was written by the reference build"),
            std::string::npos)
      << indexRefusal(other, identity());
}

TEST_F(Checkpoint, Version2FilesAreStillRead) {
  const std::uint64_t shardSum = downgradeToVersion2(shardPath(folder, 0));
  downgradeToVersion2(indexPath(folder), &shardSum);
  const CheckpointState s = readIndex(folder, identity()); // the writer is not compared
  EXPECT_EQ(s.iteration, 7u);
  EXPECT_EQ(readShard(folder, 0, identity(), s).columns.at(1).bytes, shardOf(5).columns[1].bytes);
  // A version 2 file does not say who wrote it: the general reason.
  CheckpointIdentity reference = identity();
  reference.program = identityHash("reference kernels: a");
  reference.writer = CheckpointWriter::Reference;
  EXPECT_NE(indexRefusal(folder, reference).find("written by another program"), std::string::npos)
      << indexRefusal(folder, reference);
}
