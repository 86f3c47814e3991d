//===- wash/mpi/creations.hpp - the init kernels' particles, shared out -*- C++ -*-===//
//
// Every rank runs the init kernels (they must be deterministic) and sees every
// create_particle call, but stores only its own: blocks of `block` consecutive
// creation indices dealt round-robin over the ranks. An init loop that walks
// space in order then gives each rank spatially coherent pieces, and no rank
// ever holds more than its share plus a block (plus one scratch row). Instead
// of comparing the particles themselves, the ranks compare the number of
// creations and a digest of every call's arguments.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/run_output.hpp>
#include <wash/mpi/comm.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace wash::mpi {

class Creations {
public:
  /// Consecutive creation indices stored together. WASH_MPI_CREATION_BLOCK
  /// overrides it (tests use small blocks to deal small scenes out).
  static std::uint64_t blockSize() {
    static const std::uint64_t size = [] {
      const char *text = std::getenv("WASH_MPI_CREATION_BLOCK");
      const long long value = text ? std::atoll(text) : 0;
      return value > 0 ? std::uint64_t(value) : std::uint64_t(4096);
    }();
    return size;
  }

  /// A new particle: counts and digests it, drops the previous scratch row,
  /// and returns its id (the creation index). Unless this rank keeps it, the
  /// row create_particle now appends is scratch: the init kernel may still
  /// write to it through the returned reference, and the next creation or
  /// finish() removes it.
  template <typename Particles, typename V>
  std::uint64_t create(Particles &P, double density, double mass, double smoothingLength,
                       const V &pos, const V &vel) {
    dropScratch(P);
    if (ranks_ == 0)
      rank_ = rank(), ranks_ = ranks();
    digest(density), digest(mass), digest(smoothingLength), digest(pos), digest(vel);
    const std::uint64_t id = count_++;
    scratch_ = (id / blockSize()) % std::uint64_t(ranks_) != std::uint64_t(rank_);
    mostRows_ = std::max<std::uint64_t>(mostRows_, P.size() + 1);
    return id;
  }

  /// After the init kernels: drops the scratch row, then (collective) checks
  /// that every rank saw the same creations.
  template <typename Particles> void finish(Particles &P) {
    dropScratch(P);
    const std::uint64_t seen = digest_ ^ (count_ * 0x9e3779b97f4a7c15ull);
    if (allreduceMin(count_) != allreduceMax(count_) || allreduceMin(seen) != allreduceMax(seen))
      throw ::wash::detail::RunError(
          "the init kernels created different particles on different ranks; with the MPI "
          "backend they run on every rank and must be deterministic");
  }

  /// The most rows (kept particles and the scratch row) this rank held while
  /// the init kernels ran.
  std::uint64_t mostRows() const { return mostRows_; }

private:
  template <typename Particles> void dropScratch(Particles &P) {
    if (scratch_)
      P.forEachColumn([](auto &column) { column.pop_back(); });
    scratch_ = false;
  }

  /// FNV-1a over the value's bytes.
  template <typename T> void digest(const T &value) {
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof bytes);
    for (unsigned char b : bytes)
      digest_ = (digest_ ^ b) * 1099511628211ull;
  }

  std::uint64_t count_ = 0, mostRows_ = 0;
  std::uint64_t digest_ = 1469598103934665603ull;
  int rank_ = 0, ranks_ = 0;
  bool scratch_ = false;
};

} // namespace wash::mpi
