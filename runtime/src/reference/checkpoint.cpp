//===- checkpoint.cpp - checkpoint and restart of the reference runtime -===//
//
// The reference's store in the shared checkpoint format (wash/detail/
// checkpoint.hpp): one shard with every column of the store at full
// precision, forces by name ("scalar:<name>", "vector:<name>", each padded
// to the store's size with the zeros a shorter column reads as).
//
//===----------------------------------------------------------------------===//
#include "checkpoint.hpp"

#include <wash/detail/checkpoint.hpp>

#include <chrono>
#include <cstring>

namespace wash::detail {
namespace {

template <typename T>
Shard::Column columnOf(const std::string &name, const std::vector<T> &v, std::size_t n) {
  Shard::Column c{{name, std::uint32_t(sizeof(T))}, std::vector<char>(n * sizeof(T), 0)};
  std::memcpy(c.bytes.data(), v.data(), std::min(n, v.size()) * sizeof(T));
  return c;
}

template <typename T>
void fill(std::vector<T> &v, const Shard &shard, const std::string &name, const std::string &from) {
  for (const Shard::Column &c : shard.columns)
    if (c.field.name == name && c.field.elementBytes == sizeof(T)) {
      v.resize(shard.particles);
      std::memcpy(static_cast<void *>(v.data()), c.bytes.data(), c.bytes.size());
      return;
    }
  throw RunError("cannot restart from checkpoint '" + from + "': it has no column '" + name + "'");
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string forceColumn(const Force &f) { return (f.isVector ? "vector:" : "scalar:") + f.name; }

/// The builtin columns and the forces main registered: what a restart of the
/// same program knows before any kernel ran.
std::vector<CheckpointField> fields(const State &s) {
  std::vector<CheckpointField> out = {{"id", 8},
                                      {"pos", sizeof(ParticleVec)},
                                      {"vel", sizeof(ParticleVec)},
                                      {"acc", sizeof(ParticleVec)},
                                      {"density", 8},
                                      {"mass", 8},
                                      {"smoothing_length", 8}};
  if (!s.types.empty()) // a typed simulation: each particle's type
    out.push_back({"type", std::uint32_t(sizeof(std::uint32_t))});
  for (const Force &f : s.forces)
    if (f.registered)
      out.push_back({forceColumn(f), std::uint32_t(f.isVector ? sizeof(ParticleVec) : 8)});
  return out;
}

void write(Run &run, const State &s, std::uint64_t step) {
  const ProfileScope profiled("checkpoint");
  const auto start = std::chrono::steady_clock::now();
  const ParticleStore &p = s.particles;
  const std::size_t n = p.size();
  Shard shard;
  shard.particles = n;
  shard.columns = {columnOf("id", p.id, n),
                   columnOf("pos", p.pos, n),
                   columnOf("vel", p.vel, n),
                   columnOf("acc", p.acc, n),
                   columnOf("density", p.density, n),
                   columnOf("mass", p.mass, n),
                   columnOf("smoothing_length", p.smoothingLength, n)};
  if (!s.types.empty())
    shard.columns.push_back(columnOf("type", p.type, n));
  static const std::vector<double> noScalars;
  static const std::vector<ParticleVec> noVectors;
  for (const Force &f : s.forces)
    shard.columns.push_back(
        f.isVector
            ? columnOf(forceColumn(f), f.slot < p.vectors.size() ? p.vectors[f.slot] : noVectors, n)
            : columnOf(forceColumn(f), f.slot < p.scalars.size() ? p.scalars[f.slot] : noScalars,
                       n));
  const std::string folder = checkpointFolder(run.checkpointDir(), step);
  const std::string partial = partialFolder(folder);
  const CheckpointIdentity id = run.identity(fields(s));
  beginCheckpoint(partial);
  CheckpointState state = run.checkpointState(step, 1, n);
  state.shardChecksums = {writeShard(shardPath(partial, 0), id, shard)};
  writeIndex(indexPath(partial), id, state);
  completeCheckpoint(partial, folder, programOptions().keepCheckpoints);
  run.checkpointWritten(folder, step, secondsSince(start));
}

} // namespace

std::string referenceProgram(const State &s) {
  static const char *kinds[] = {"init", "update", "force", "void", "reduction"};
  std::string text = "reference kernels:";
  for (const Kernel &k : s.kernels)
    text += std::string(" ") + kinds[k.kind] + " " + k.name + ";";
  return text;
}

void checkpointAfterStep(Run &run, const State &s, std::uint64_t step) {
  const bool stop = stopSignal() != 0;
  if (run.checkpointDue() || stop)
    write(run, s, step);
  if (stop) {
    run.stopped();
    const std::string folder = checkpointFolder(run.checkpointDir(), step);
    throw Interrupted("stopped by a signal after iteration " + std::to_string(step) +
                      "; checkpoint written to " + folder + " (continue with --restart " + folder +
                      ")");
  }
}

void restoreCheckpoint(Run &run, State &s) {
  const auto start = std::chrono::steady_clock::now();
  const CheckpointIdentity id = run.identity(fields(s));
  const std::string folder = resolveRestart(programOptions().restartPath);
  const CheckpointState saved = readIndex(folder, id);
  ParticleStore &p = s.particles;
  for (std::uint32_t k = 0; k < saved.shards; ++k) { // one, unless another program wrote it
    Shard shard = readShard(folder, k, id, saved);
    if (saved.shards != 1)
      throw RunError("cannot restart from checkpoint '" + folder + "': it has " +
                     std::to_string(saved.shards) + " shards; the reference writes one");
    fill(p.id, shard, "id", folder);
    fill(p.pos, shard, "pos", folder);
    fill(p.vel, shard, "vel", folder);
    fill(p.acc, shard, "acc", folder);
    fill(p.density, shard, "density", folder);
    fill(p.mass, shard, "mass", folder);
    fill(p.smoothingLength, shard, "smoothing_length", folder);
    if (!s.types.empty())
      fill(p.type, shard, "type", folder);
    // Forces created on first use are created here, as the kernels did.
    for (const Shard::Column &c : shard.columns) {
      const std::string &name = c.field.name;
      const bool vector = name.rfind("vector:", 0) == 0;
      if (!vector && name.rfind("scalar:", 0) != 0)
        continue;
      const Force &f = s.force(name.substr(7), vector, CallSite::current());
      if (vector) {
        p.vectors.resize(std::max(p.vectors.size(), f.slot + 1));
        fill(p.vectors[f.slot], shard, name, folder);
      } else {
        p.scalars.resize(std::max(p.scalars.size(), f.slot + 1));
        fill(p.scalars[f.slot], shard, name, folder);
      }
    }
  }
  run.resume(saved, p.size(), folder, secondsSince(start));
}

} // namespace wash::detail
