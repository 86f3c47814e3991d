//===- wash/detail/random.hpp - the hash behind wash::random -----*- C++ -*-===//
#pragma once

#include <cstdint>

namespace wash::detail {

/// SplitMix64's finaliser (Steele, Lea and Flood, 2014; Stafford's variant
/// 13): a bijection of 64-bit words that mixes every input bit into every
/// output bit.
constexpr std::uint64_t mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// 64 random bits of (key, step, stream): three mixing rounds, each taking one
/// input scaled by its own odd constant. Each round is a bijection, so for one
/// step and stream distinct keys never give the same bits.
constexpr std::uint64_t randomBits(std::uint64_t key, std::uint64_t step, std::uint64_t stream) {
  std::uint64_t x = mix64(key * 0x9e3779b97f4a7c15ULL + 0x6a09e667f3bcc909ULL);
  x = mix64(x ^ (step * 0xd1b54a32d192ed03ULL + 0xbb67ae8584caa73bULL));
  return mix64(x ^ (stream * 0xaef17502108ef2d9ULL + 0x3c6ef372fe94f82bULL));
}

/// The top 53 bits as a double in [0, 1).
constexpr double unitInterval(std::uint64_t bits) { return double(bits >> 11) * 0x1.0p-53; }

/// wash::random and wash::random_normal at an explicit step.
constexpr double randomUniform(std::uint64_t key, std::uint64_t step, std::uint64_t stream) {
  return unitInterval(randomBits(key, step, stream));
}
double randomNormal(std::uint64_t key, std::uint64_t step, std::uint64_t stream);

/// The step wash::random uses now: 0 before the first step (main, init
/// kernels), then the step whose kernels run (wash/detail/run.hpp keeps it).
std::uint64_t randomStep();

} // namespace wash::detail
