// wash/random.hpp: a pure function of (key, step, stream), pinned to values an
// independent Python implementation of the same hash gives, uniform enough
// for physics, and independent of the order of the calls.
#include <wash/detail/random.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/random.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

namespace {

using wash::detail::randomBits;
using wash::detail::randomUniform;

/// Runs `body` as if in step `step` of a run, then back to the set-up.
template <typename Body> void inStep(std::uint64_t step, Body body) {
  wash::detail::runStage().step = step;
  body();
  wash::detail::runStage().step = 0;
}

TEST(Random, KnownValues) {
  // A change of these is a change of every seeded run: a new version of the
  // generator, to be documented as such.
  EXPECT_EQ(randomBits(0, 0, 0), 0xdaee2f0cc741d33eULL);
  EXPECT_EQ(randomBits(1, 0, 0), 0xe6ab8dbff1f7a8e9ULL);
  EXPECT_EQ(randomBits(0, 1, 0), 0x64717ec15516795eULL);
  EXPECT_EQ(randomBits(0, 0, 1), 0xb221c7f789d988f9ULL);
  EXPECT_EQ(randomBits(141, 7, 3), 0x420dcb206ec61037ULL);
  EXPECT_EQ(randomBits(~0ULL, ~0ULL, ~0ULL), 0x97c72b2791e670bbULL);
  EXPECT_EQ(randomUniform(0, 0, 0), 0x1.b5dc5e198e83ap-1);
  EXPECT_EQ(randomUniform(141, 7, 3), 0x1.08372c81bb184p-2);
}

TEST(Random, TheCurrentStepIsTheRunStage) {
  // Step 0 set explicitly: a run test before this one in the same process
  // leaves the stage at its last step.
  inStep(0, [] {
    EXPECT_EQ(wash::random(141, 3), randomUniform(141, 0, 3)) << "set-up and init kernels";
  });
  inStep(7, [] {
    EXPECT_EQ(wash::random(141, 3), randomUniform(141, 7, 3));
    EXPECT_EQ(wash::random(141), randomUniform(141, 7, 0));
    EXPECT_EQ(wash::random_normal(141, 3), wash::detail::randomNormal(141, 7, 3));
  });
}

TEST(Random, NoDependenceOnCallOrder) {
  constexpr int n = 1000;
  std::vector<double> forward(n), backward(n);
  inStep(5, [&] {
    for (int k = 0; k < n; ++k)
      forward[k] = wash::random(k, k % 3);
    for (int k = n - 1; k >= 0; --k) {
      backward[k] = wash::random(k, k % 3);
      wash::random_normal(k, 1); // other draws in between change nothing
    }
  });
  EXPECT_EQ(forward, backward);
}

TEST(Random, InHalfOpenUnitIntervalWith53Bits) {
  bool lowBitSeen = false;
  for (std::uint64_t k = 0; k < 100000; ++k) {
    const double u = randomUniform(k, 3, 0);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ASSERT_EQ(std::ldexp(u, 53), std::floor(std::ldexp(u, 53))) << "a multiple of 2^-53";
    lowBitSeen |= std::fmod(std::ldexp(u, 53), 2.0) == 1.0;
  }
  EXPECT_TRUE(lowBitSeen) << "the last of the 53 bits is used";
  EXPECT_EQ(wash::detail::unitInterval(~0ULL), 1.0 - 0x1.0p-53);
  EXPECT_EQ(wash::detail::unitInterval(0), 0.0);
}

TEST(Random, KeysStepsAndStreamsDrawDistinctNumbers) {
  std::set<std::uint64_t> seen;
  for (std::uint64_t k = 0; k < 20000; ++k)
    for (std::uint64_t s = 0; s < 3; ++s)
      for (std::uint64_t t = 0; t < 3; ++t)
        seen.insert(randomBits(k, s, t));
  EXPECT_EQ(seen.size(), 20000u * 9u);
}

/// Pearson's chi-squared of `values` in [0, 1) over `bins` equal bins.
template <typename Draw> double chiSquared(int count, int bins, Draw draw) {
  std::vector<double> hits(bins);
  for (int i = 0; i < count; ++i)
    hits[std::size_t(draw(i) * bins)] += 1.0;
  const double expected = double(count) / bins;
  double chi2 = 0.0;
  for (double h : hits)
    chi2 += (h - expected) * (h - expected) / expected;
  return chi2;
}

TEST(Random, Uniform) {
  // 100 bins, 99 degrees of freedom: P(chi2 > 160) < 1e-4. Over consecutive
  // keys (a kernel's ids), steps and streams, the three ways kernels vary them.
  constexpr int n = 200000;
  EXPECT_LT(chiSquared(n, 100, [](int i) { return randomUniform(i, 1, 0); }), 160.0);
  EXPECT_LT(chiSquared(n, 100, [](int i) { return randomUniform(42, i, 0); }), 160.0);
  EXPECT_LT(chiSquared(n, 100, [](int i) { return randomUniform(42, 1, i); }), 160.0);
  // Successive steps of one key are not correlated.
  double sum = 0.0, product = 0.0;
  for (int i = 0; i < n; ++i) {
    const double a = randomUniform(7, i, 0) - 0.5, b = randomUniform(7, i + 1, 0) - 0.5;
    sum += a;
    product += a * b;
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(product / n, 0.0, 4.0 / 12.0 / std::sqrt(double(n)));
}

TEST(Random, Normal) {
  constexpr int n = 200000;
  double sum = 0.0, squares = 0.0, fourth = 0.0;
  int beyondTwo = 0;
  for (int i = 0; i < n; ++i) {
    const double z = wash::detail::randomNormal(i, 2, 1);
    ASSERT_TRUE(std::isfinite(z));
    sum += z;
    squares += z * z;
    fourth += z * z * z * z;
    beyondTwo += std::fabs(z) > 2.0;
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 / std::sqrt(double(n)));
  EXPECT_NEAR(squares / n, 1.0, 4.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(fourth / n, 3.0, 4.0 * std::sqrt(96.0 / n)); // a normal's kurtosis
  // P(|z| > 2) = 0.0455; its standard deviation over n draws is 0.00047.
  EXPECT_NEAR(double(beyondTwo) / n, 0.0455, 0.002);
}

} // namespace
