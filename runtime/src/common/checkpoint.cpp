// Checkpoint files (wash/detail/checkpoint.hpp; the format is in
// docs/semantics.md, "Checkpoint and restart").
#include <wash/detail/checkpoint.hpp>
#include <wash/detail/output_folder.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace wash::detail {
namespace {

constexpr char indexMagic[8] = {'W', 'A', 'S', 'H', 'C', 'K', 'P', 'T'};
constexpr char shardMagic[8] = {'W', 'A', 'S', 'H', 'S', 'H', 'R', 'D'};
// 2: the index holds its shards' checksums; 3: the identity says which kind of
// program wrote it (version 2 files are still read, their writer Unknown).
constexpr std::uint32_t formatVersion = 3;
constexpr std::uint32_t oldestReadVersion = 2;

/// A 64-bit checksum over a byte stream, eight bytes at a time: each step is
/// a bijection of the state, so any one changed word changes the result.
class Checksum {
public:
  void add(const void *data, std::size_t n) {
    const auto *p = static_cast<const unsigned char *>(data);
    length_ += n;
    while (carried_ && n) {
      pending_[carried_++] = *p++, --n;
      if (carried_ == 8)
        flushPending();
    }
    for (; n >= 8; p += 8, n -= 8) {
      std::uint64_t w;
      std::memcpy(&w, p, 8);
      word(w);
    }
    while (n)
      pending_[carried_++] = *p++, --n;
  }
  std::uint64_t value() const {
    Checksum c = *this;
    if (c.carried_) {
      std::memset(c.pending_ + c.carried_, 0, 8 - c.carried_);
      c.flushPending();
    }
    c.word(c.length_);
    std::uint64_t h = c.h_;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    return h;
  }

private:
  void word(std::uint64_t w) {
    h_ ^= w * 0x9e3779b97f4a7c15ull;
    h_ = ((h_ << 31) | (h_ >> 33)) * 0xc4ceb9fe1a85ec53ull;
  }
  void flushPending() {
    std::uint64_t w;
    std::memcpy(&w, pending_, 8);
    word(w);
    carried_ = 0;
  }
  std::uint64_t h_ = 0x243f6a8885a308d3ull, length_ = 0;
  unsigned char pending_[8];
  int carried_ = 0;
};

/// Little-endian (the machines wash runs on) fields, appended to a header.
struct Encoder {
  std::string bytes;
  template <typename T> void put(T v) {
    bytes.append(reinterpret_cast<const char *>(&v), sizeof v);
  }
  void text(const std::string &s) {
    put(std::uint32_t(s.size()));
    bytes += s;
  }
  void identity(const CheckpointIdentity &id) {
    text(id.simulation);
    text(id.program);
    put(std::uint8_t(id.writer));
    put(id.dimensions);
    put(std::uint8_t(id.useFloat));
    put(std::uint32_t(id.fields.size()));
    for (const CheckpointField &f : id.fields) {
      text(f.name);
      put(f.elementBytes);
    }
  }
};

/// Reads what Encoder wrote, refusing to read past the end.
struct Decoder {
  const std::vector<char> &file;
  std::size_t at = 0;
  const std::string &path;
  std::uint32_t version = formatVersion;
  template <typename T> T get() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, file.data() + at, sizeof v);
    at += sizeof v;
    return v;
  }
  std::string text() {
    const std::uint32_t n = get<std::uint32_t>();
    need(n);
    std::string s(file.data() + at, n);
    at += n;
    return s;
  }
  void need(std::uint64_t n) const {
    if (n > file.size() - 8 - at) // the last 8 bytes are the checksum
      throw RunError("checkpoint file '" + path + "' is truncated (" + std::to_string(file.size()) +
                     " bytes, its header announces more)");
  }
  CheckpointIdentity identity() {
    CheckpointIdentity id;
    id.simulation = text();
    id.program = text();
    if (version >= 3) {
      const std::uint8_t writer = get<std::uint8_t>();
      id.writer = writer <= std::uint8_t(CheckpointWriter::Translated) ? CheckpointWriter(writer)
                                                                       : CheckpointWriter::Unknown;
    }
    id.dimensions = get<std::uint32_t>();
    id.useFloat = get<std::uint8_t>() != 0;
    const std::uint32_t n = get<std::uint32_t>();
    for (std::uint32_t k = 0; k < n; ++k) {
      CheckpointField f;
      f.name = text();
      f.elementBytes = get<std::uint32_t>();
      id.fields.push_back(f);
    }
    return id;
  }
};

std::string fieldNames(const std::vector<CheckpointField> &fields) {
  std::string names;
  for (const CheckpointField &f : fields)
    names += (names.empty() ? "" : ", ") + f.name + " (" + std::to_string(f.elementBytes) + " B)";
  return names;
}

/// Why a checkpoint of `got` cannot restart a program of `want` ("" if it can).
/// The most specific reason first: a float build reading a double checkpoint
/// is told about the precision, whatever else differs.
std::string mismatch(const CheckpointIdentity &got, const CheckpointIdentity &want) {
  auto precision = [](bool f) { return f ? "float" : "double"; };
  if (got.dimensions != want.dimensions)
    return "it is of a " + std::to_string(got.dimensions) + "D simulation; this program is " +
           std::to_string(want.dimensions) + "D";
  if (got.useFloat != want.useFloat)
    return std::string("it holds ") + precision(got.useFloat) +
           "-precision state; this program stores " + precision(want.useFloat) +
           " (set_precision): restart with a build of the same precision";
  if (got.simulation != want.simulation)
    return "it is of simulation '" + got.simulation + "'; this program runs '" + want.simulation +
           "'";
  using enum CheckpointWriter;
  if (got.program != want.program && got.writer != Unknown && got.writer != want.writer)
    return got.writer == Translated
               ? "it was written by a translated program; a reference build restarts only from "
                 "its own checkpoints"
               : "it was written by the reference build (the untranslated program); a "
                 "translated program restarts only from checkpoints of a translated build";
  if (got.program != want.program)
    return "it was written by another program (kernels or columns differ: program " + got.program +
           ", this one " + want.program + ")";
  if (got.fields != want.fields)
    return "its columns are " + fieldNames(got.fields) + "; this program's are " +
           fieldNames(want.fields);
  return "";
}

/// The whole file, its magic and version checked (throws RunError, saying
/// why); `version` is set to the file's.
std::vector<char> readChecked(const std::string &path, const char (&magic)[8],
                              std::uint32_t &version) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw RunError("cannot read checkpoint file '" + path + "': " + std::strerror(errno));
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  std::vector<char> file(ec ? 0 : std::size_t(size));
  if (!in.read(file.data(), std::streamsize(file.size())))
    throw RunError("cannot read checkpoint file '" + path + "': " + std::strerror(errno));
  if (file.size() < 8 + 4 + 8 || std::memcmp(file.data(), magic, 8) != 0)
    throw RunError("'" + path + "' is not a wash checkpoint file" +
                   (file.size() < 20 ? " (it is truncated or empty)" : ""));
  std::memcpy(&version, file.data() + 8, 4);
  if (version < oldestReadVersion || version > formatVersion)
    throw RunError("checkpoint file '" + path + "' has format version " + std::to_string(version) +
                   "; this program reads versions " + std::to_string(oldestReadVersion) + " to " +
                   std::to_string(formatVersion));
  return file;
}

void verifyChecksum(const std::vector<char> &file, std::size_t end, const std::string &path) {
  if (file.size() != end + 8)
    throw RunError("checkpoint file '" + path + "' is " +
                   (file.size() < end + 8 ? "truncated" : "longer than its header announces") +
                   " (" + std::to_string(file.size()) + " bytes, expected " +
                   std::to_string(end + 8) + ")");
  Checksum sum;
  sum.add(file.data(), end);
  std::uint64_t stored;
  std::memcpy(&stored, file.data() + end, 8);
  if (stored != sum.value())
    throw RunError("checkpoint file '" + path +
                   "' is corrupted: its checksum does not match its contents");
}

/// Writes header, then the blocks, then the checksum, into a temporary file
/// renamed onto `path`; returns the checksum.
std::uint64_t writeAtomically(const std::string &path, const std::string &header,
                              const std::vector<const std::vector<char> *> &blocks) {
  const std::string partial = partialPath(path);
  std::ofstream out(partial, std::ios::binary);
  if (!out)
    throw RunError("cannot open '" + partial + "' for writing: " + std::strerror(errno));
  Checksum sum;
  sum.add(header.data(), header.size());
  out.write(header.data(), std::streamsize(header.size()));
  for (const std::vector<char> *b : blocks) {
    sum.add(b->data(), b->size());
    out.write(b->data(), std::streamsize(b->size()));
  }
  const std::uint64_t value = sum.value();
  out.write(reinterpret_cast<const char *>(&value), sizeof value);
  out.close();
  std::error_code ec;
  if (!out) {
    fs::remove(partial, ec);
    throw RunError("error while writing checkpoint file '" + path + "': " + std::strerror(errno));
  }
  fs::rename(partial, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(partial, ignored);
    throw RunError("cannot write checkpoint file '" + path + "': " + ec.message());
  }
  return value;
}

Encoder headerOf(const char (&magic)[8]) {
  Encoder e;
  e.bytes.append(magic, 8);
  e.put(formatVersion);
  return e;
}

/// The iteration of a complete checkpoint folder named checkpoint_<digits>, or -1.
long long completeIteration(const fs::path &p) {
  const std::string name = p.filename().string();
  const std::string prefix = "checkpoint_";
  if (name.rfind(prefix, 0) != 0 || name.size() == prefix.size())
    return -1;
  for (std::size_t k = prefix.size(); k < name.size(); ++k)
    if (name[k] < '0' || name[k] > '9')
      return -1;
  std::error_code ec;
  if (!fs::is_regular_file(p / "index.wck", ec))
    return -1;
  return std::stoll(name.substr(prefix.size()));
}

volatile std::sig_atomic_t receivedSignal = 0;

extern "C" void onStopSignal(int signal) {
  if (receivedSignal) { // the second: end now
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  receivedSignal = signal;
}

} // namespace

std::string checkpointFolder(const std::string &dir, std::uint64_t iteration) {
  char name[40];
  std::snprintf(name, sizeof name, "checkpoint_%06llu", (unsigned long long)iteration);
  return (fs::path(dir) / name).string();
}
std::string partialFolder(const std::string &folder) { return folder + ".partial"; }
std::string shardPath(const std::string &folder, std::uint32_t shard) {
  char name[32];
  std::snprintf(name, sizeof name, "shard_%05u.wck", shard);
  return (fs::path(folder) / name).string();
}
std::string indexPath(const std::string &folder) {
  return (fs::path(folder) / "index.wck").string();
}

void beginCheckpoint(const std::string &partial) {
  std::error_code ec;
  fs::remove_all(partial, ec);
  fs::create_directories(partial, ec);
  if (ec || !fs::is_directory(partial))
    throw RunError("cannot create checkpoint folder '" + partial +
                   "': " + (ec ? ec.message() : "not a directory"));
}

std::string checkpointDirectory(const RunOptions &o) {
  return o.checkpointDir.empty() ? (fs::path(o.outDir) / "checkpoints").string() : o.checkpointDir;
}

std::uint64_t writeShard(const std::string &path, const CheckpointIdentity &id,
                         const Shard &shard) {
  Encoder e = headerOf(shardMagic);
  CheckpointIdentity own = id;
  own.fields.clear();
  for (const Shard::Column &c : shard.columns)
    own.fields.push_back(c.field);
  e.identity(own);
  e.put(shard.particles);
  std::vector<const std::vector<char> *> blocks;
  for (const Shard::Column &c : shard.columns)
    blocks.push_back(&c.bytes);
  return writeAtomically(path, e.bytes, blocks);
}

void writeIndex(const std::string &path, const CheckpointIdentity &id, const CheckpointState &s) {
  Encoder e = headerOf(indexMagic);
  e.identity(id);
  e.put(s.iteration);
  e.put(s.time);
  e.put(s.timeStep);
  e.put(std::uint8_t(s.timeStepSet));
  e.put(std::uint8_t(s.stopRequested));
  e.put(std::uint32_t(s.variables.size()));
  for (const auto &[name, value] : s.variables) {
    e.text(name);
    e.put(value);
  }
  e.put(s.nextOutput);
  e.put(s.nextCheckpoint);
  e.put(std::uint8_t(s.seriesByTime));
  e.put(std::uint64_t(s.frames.size()));
  for (const RunOutput::Written &w : s.frames) {
    e.put(w.step);
    e.put(w.time);
    e.text(w.file);
  }
  e.put(s.shards);
  e.put(s.particles);
  if (s.shardChecksums.size() != s.shards)
    throw RunError("cannot write checkpoint file '" + path +
                   "': " + std::to_string(s.shardChecksums.size()) + " shard checksums for " +
                   std::to_string(s.shards) + " shards");
  for (std::uint64_t sum : s.shardChecksums)
    e.put(sum);
  writeAtomically(path, e.bytes, {});
}

void completeCheckpoint(const std::string &partial, const std::string &folder, std::uint64_t keep) {
  std::error_code ec;
  fs::remove_all(folder, ec); // the same iteration, written again
  fs::rename(partial, folder, ec);
  if (ec)
    throw RunError("cannot complete checkpoint '" + folder + "': " + ec.message());
  std::vector<std::pair<long long, fs::path>> complete;
  for (const fs::directory_entry &d : fs::directory_iterator(fs::path(folder).parent_path(), ec))
    if (long long it = completeIteration(d.path()); it >= 0)
      complete.emplace_back(it, d.path());
  std::sort(complete.begin(), complete.end());
  for (std::size_t k = 0; k + keep < complete.size(); ++k)
    if (complete[k].second != fs::path(folder))
      fs::remove_all(complete[k].second, ec);
}

std::string resolveRestart(const std::string &path) {
  std::error_code ec;
  if (fs::is_regular_file(fs::path(path) / "index.wck", ec))
    return path;
  if (!fs::is_directory(path, ec))
    throw RunError("cannot restart from '" + path + "': no such checkpoint or folder");
  long long newest = -1;
  fs::path best;
  for (const fs::directory_entry &d : fs::directory_iterator(path, ec))
    if (long long it = completeIteration(d.path()); it > newest)
      newest = it, best = d.path();
  if (newest < 0)
    throw RunError("cannot restart from '" + path +
                   "': it holds no complete checkpoint (a folder checkpoint_<iteration> with "
                   "an index.wck)");
  return best.string();
}

CheckpointState readIndex(const std::string &folder, const CheckpointIdentity &expected) {
  const std::string path = indexPath(folder);
  std::uint32_t version = 0;
  const std::vector<char> file = readChecked(path, indexMagic, version);
  Decoder d{file, 12, path, version};
  CheckpointIdentity got;
  CheckpointState s;
  try {
    got = d.identity();
    s.iteration = d.get<std::uint64_t>();
    s.time = d.get<double>();
    s.timeStep = d.get<double>();
    s.timeStepSet = d.get<std::uint8_t>() != 0;
    s.stopRequested = d.get<std::uint8_t>() != 0;
    for (std::uint32_t n = d.get<std::uint32_t>(), k = 0; k < n; ++k) {
      std::string name = d.text();
      s.variables.emplace_back(name, d.get<double>());
    }
    s.nextOutput = d.get<std::uint64_t>();
    s.nextCheckpoint = d.get<std::uint64_t>();
    s.seriesByTime = d.get<std::uint8_t>() != 0;
    for (std::uint64_t n = d.get<std::uint64_t>(), k = 0; k < n; ++k) {
      RunOutput::Written w;
      w.step = d.get<std::uint64_t>();
      w.time = d.get<double>();
      w.file = d.text();
      s.frames.push_back(w);
    }
    s.shards = d.get<std::uint32_t>();
    s.particles = d.get<std::uint64_t>();
    for (std::uint32_t k = 0; k < s.shards; ++k)
      s.shardChecksums.push_back(d.get<std::uint64_t>());
  } catch (const RunError &) { // a cut file, or a corrupted length that reads past the end
    throw RunError("checkpoint file '" + path + "' is truncated or corrupted (" +
                   std::to_string(file.size()) + " bytes, its header announces more)");
  }
  verifyChecksum(file, d.at, path);
  if (std::string bad = mismatch(got, expected); !bad.empty())
    throw RunError("cannot restart from checkpoint '" + folder + "': " + bad);
  if (s.shards == 0)
    throw RunError("checkpoint file '" + path + "' names no shard");
  return s;
}

Shard readShard(const std::string &folder, std::uint32_t shard, const CheckpointIdentity &expected,
                const CheckpointState &index) {
  const std::string path = shardPath(folder, shard);
  std::uint32_t version = 0;
  const std::vector<char> file = readChecked(path, shardMagic, version);
  Decoder d{file, 12, path, version};
  CheckpointIdentity got = d.identity();
  Shard s;
  s.particles = d.get<std::uint64_t>();
  std::uint64_t bytes = 0;
  for (const CheckpointField &f : got.fields)
    bytes += f.elementBytes * s.particles;
  verifyChecksum(file, d.at + bytes, path);
  std::uint64_t stored;
  std::memcpy(&stored, file.data() + file.size() - 8, 8);
  if (shard >= index.shardChecksums.size() || stored != index.shardChecksums[shard])
    throw RunError("cannot restart from checkpoint '" + folder + "': its shard file '" + path +
                   "' is not the one its index was written with (files of different "
                   "checkpoints are mixed)");
  CheckpointIdentity want = expected;
  want.fields = got.fields; // the caller matches columns by name
  if (std::string bad = mismatch(got, want); !bad.empty())
    throw RunError("cannot restart from checkpoint file '" + path + "': " + bad);
  const char *at = file.data() + d.at;
  for (const CheckpointField &f : got.fields) {
    const std::size_t n = std::size_t(f.elementBytes * s.particles);
    s.columns.push_back({f, std::vector<char>(at, at + n)});
    at += n;
  }
  return s;
}

std::uint64_t checkpointChecksum(const void *data, std::size_t bytes) {
  Checksum sum;
  sum.add(data, bytes);
  return sum.value();
}

std::string identityHash(const std::string &text) {
  Checksum sum;
  sum.add(text.data(), text.size());
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx", (unsigned long long)sum.value());
  return hex;
}

void watchStopSignals() {
  struct sigaction action{};
  action.sa_handler = onStopSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGTERM, &action, nullptr);
  sigaction(SIGINT, &action, nullptr);
}

int stopSignal() { return receivedSignal; }

} // namespace wash::detail
