//===- wash/detail/exact_sum.hpp - the exact sum every runtime does -*- C++ -*-===//
//
// A Sum reduction is the exact sum of its values, rounded once to nearest with
// ties to even (docs/semantics.md), so it does not depend on the order of the
// additions, the thread count or the rank count. ExactSum holds the sum as an
// integer in units of 2^-1074, the smallest subnormal double (every finite
// double, and so every float, is an integer there), in base-2^32 digits kept
// in signed 64-bit limbs: an add changes three limbs and carries nothing, and
// the carries are settled (normalise) long before a limb could overflow. Two
// sums merge exactly by adding limbs, which is how threads and ranks combine.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace wash::detail {

/// MaxPending: adds between normalisations (a test makes it small to
/// exercise the carries; every runtime uses ExactSum).
template <std::uint32_t MaxPending> class BasicExactSum {
public:
  /// Digits: positions 0 (2^-1074) to 2097 (the top bit of DBL_MAX) take 66;
  /// two more hold the carries of up to 2^64 values and the sign.
  static constexpr int limbCount = 68;
  /// The whole state as integers that add: limbs, then the counts of values,
  /// -0.0 values, NaNs, +inf and -inf (what an MPI reduction sends).
  static constexpr int stateSize = limbCount + 5;
  using State = std::array<std::int64_t, stateSize>;

  void add(double v) {
    addUncounted(v);
    if (++pending_ == maxPending)
      normalise();
  }
  void add(float v) { add(double(v)); } // exact: every float is a double

  /// Adds value(k) for k = 0 .. count - 1, as add() would one by one (the
  /// adds are counted per run of up to 2^30, not one by one).
  template <typename Value> void addEach(std::size_t count, Value value) {
    for (std::size_t start = 0; start < count;) {
      const std::size_t end = start + std::min<std::size_t>(count - start, maxPending - pending_);
      for (std::size_t k = start; k < end; ++k)
        addUncounted(double(value(k)));
      pending_ += std::uint32_t(end - start);
      if (pending_ == maxPending)
        normalise();
      start = end;
    }
  }

  /// Adds another sum: the result is the exact sum of both sets of values.
  void merge(const BasicExactSum &other) { merge(other.state()); }
  void merge(const State &other) {
    normalise();
    for (int i = 0; i < limbCount; ++i)
      limbs_[i] += other[i];
    normalised_ += std::uint64_t(other[limbCount]);
    negativeZeros_ += std::uint64_t(other[limbCount + 1]);
    nans_ += std::uint64_t(other[limbCount + 2]);
    plusInfs_ += std::uint64_t(other[limbCount + 3]);
    minusInfs_ += std::uint64_t(other[limbCount + 4]);
    normalise();
  }

  /// Normalised limbs (every digit in [0, 2^32), the sign in the top limb)
  /// and the counts. States of any number of sums add limb by limb without
  /// overflow for fewer than 2^31 of them (an MPI_SUM of int64).
  State state() const {
    BasicExactSum s = *this;
    s.normalise();
    State out{};
    std::copy(s.limbs_.begin(), s.limbs_.end(), out.begin());
    out[limbCount] = std::int64_t(s.normalised_);
    out[limbCount + 1] = std::int64_t(negativeZeros_);
    out[limbCount + 2] = std::int64_t(nans_);
    out[limbCount + 3] = std::int64_t(plusInfs_);
    out[limbCount + 4] = std::int64_t(minusInfs_);
    return out;
  }

  /// The exact sum rounded once to T (double or float), to nearest, ties to
  /// even; beyond T's largest finite value after rounding it is +-inf. Any
  /// NaN, or both +inf and -inf, give NaN; otherwise an infinity gives itself.
  /// An exact zero is -0.0 when every value was -0.0, else +0.0 (IEEE 754's
  /// rule for the sign of an exact zero sum; no values give +0.0).
  template <typename T> T round() const {
    static_assert(std::numeric_limits<T>::is_iec559 && std::numeric_limits<T>::radix == 2);
    if (nans_ || (plusInfs_ && minusInfs_))
      return std::numeric_limits<T>::quiet_NaN();
    if (plusInfs_ || minusInfs_)
      return plusInfs_ ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
    BasicExactSum s = *this;
    s.normalise();
    const bool negative = s.limbs_.back() < 0;
    if (negative) {
      for (std::int64_t &l : s.limbs_)
        l = -l;
      s.normalise();
    }
    int top = limbCount - 1;
    while (top >= 0 && s.limbs_[top] == 0)
      --top;
    if (top < 0)
      return s.normalised_ && negativeZeros_ == s.normalised_ ? -T(0) : T(0);
    constexpr int precision = std::numeric_limits<T>::digits;
    constexpr int lowestPosition = std::numeric_limits<T>::min_exponent - precision + 1074;
    const int highest = top * 32 + int(std::bit_width(std::uint64_t(s.limbs_[top]))) - 1;
    const int lowest = std::max(highest - precision + 1, lowestPosition);
    // Below half of T's smallest subnormal (a float's), the sum rounds to 0.
    std::uint64_t mantissa = highest >= lowest ? s.bitsFrom(lowest, highest - lowest + 1) : 0;
    if (lowest > 0 && highest >= lowest - 1 && s.bitsFrom(lowest - 1, 1) &&
        (mantissa & 1 || s.anyBitBelow(lowest - 1)))
      ++mantissa; // may reach 2^precision: still exact in T
    const int exponent = lowest - 1074;
    if (exponent + int(std::bit_width(mantissa)) - 1 >= std::numeric_limits<T>::max_exponent)
      return negative ? -std::numeric_limits<T>::infinity() : std::numeric_limits<T>::infinity();
    const T magnitude = std::ldexp(T(mantissa), exponent);
    return negative ? -magnitude : magnitude;
  }

private:
  /// Adds v to the limbs (or counts it if it is NaN or infinite); the
  /// caller counts it in pending_.
  void addUncounted(double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    const int biased = int(bits >> 52) & 0x7ff;
    std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
    // Counters in memory are int64-sized and so might alias the limbs: they
    // change only on the rare branches.
    if (biased == 0x7ff) [[unlikely]] {
      (mantissa ? nans_ : bits >> 63 ? minusInfs_ : plusInfs_) += 1;
      return;
    }
    if (bits == negativeZeroBits) [[unlikely]]
      ++negativeZeros_;
    int position = 0; // of the mantissa's lowest bit, in units of 2^-1074
    if (biased) {
      mantissa |= std::uint64_t(1) << 52;
      position = biased - 1;
    }
    const int shift = position & 31; // the mantissa << shift spans three digits
    const std::uint64_t low = mantissa << shift, high = (mantissa >> 1) >> (63 - shift);
    const std::int64_t minus = -std::int64_t(bits >> 63); // 0 or all ones
    auto signed_ = [minus](std::uint64_t digit) { return (std::int64_t(digit) ^ minus) - minus; };
    std::int64_t *limb = &limbs_[position >> 5];
    // Top digit first: in order, g++ -O3 pairs the upper two into one
    // 16-byte load and store, and an add a limb away then stalls on loading
    // half of what that store wrote.
    limb[2] += signed_(high);
    limb[0] += signed_(low & digitMask);
    limb[1] += signed_(low >> 32);
  }

  static constexpr std::uint64_t digitMask = 0xffffffff;
  static constexpr std::uint64_t negativeZeroBits = std::uint64_t(1) << 63;
  /// A limb gains less than 2^32 in magnitude per add, so 2^30 adds after a
  /// normalise (limbs below 2^32) keep every limb below 2^63.
  static_assert(MaxPending >= 1 && MaxPending <= std::uint32_t(1) << 30);
  static constexpr std::uint32_t maxPending = MaxPending;

  /// Carries: every limb but the top one becomes a digit in [0, 2^32).
  void normalise() {
    for (int i = 0; i + 1 < limbCount; ++i) {
      const std::int64_t carry = limbs_[i] >> 32; // arithmetic: floor division
      limbs_[i] -= carry * (std::int64_t(1) << 32);
      limbs_[i + 1] += carry;
    }
    normalised_ += pending_;
    pending_ = 0;
  }
  /// Bits [from, from + count) of a normalised non-negative sum; count <= 64.
  std::uint64_t bitsFrom(int from, int count) const {
    __extension__ using Wide = unsigned __int128;
    const int d = from / 32;
    Wide window = 0;
    for (int k = 2; k >= 0; --k)
      window = (window << 32) | Wide(d + k < limbCount ? std::uint64_t(limbs_[d + k]) : 0);
    window >>= from % 32;
    return std::uint64_t(window) &
           (count == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << count) - 1);
  }
  bool anyBitBelow(int position) const {
    const int d = position / 32;
    if (std::uint64_t(limbs_[d]) & ((std::uint64_t(1) << (position % 32)) - 1))
      return true;
    return std::any_of(limbs_.begin(), limbs_.begin() + d, [](std::int64_t l) { return l != 0; });
  }

  std::array<std::int64_t, limbCount> limbs_{};
  std::uint32_t pending_ = 0;    ///< values added since the last normalise
  std::uint64_t normalised_ = 0; ///< values added before it
  std::uint64_t negativeZeros_ = 0, nans_ = 0, plusInfs_ = 0, minusInfs_ = 0;
};

using ExactSum = BasicExactSum<std::uint32_t(1) << 30>;

} // namespace wash::detail
