// wash/random.hpp: the same in the reference and every backend.
#include <wash/detail/random.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/random.hpp>

#include <cmath>

namespace wash {
namespace detail {

std::uint64_t randomStep() { return runStage().step; }

double randomNormal(std::uint64_t key, std::uint64_t step, std::uint64_t stream) {
  const std::uint64_t bits = randomBits(key, step, stream);
  // 1 - u is in (0, 1]: the logarithm is finite. The second uniform number
  // is the first's bits mixed once more.
  const double u1 = 1.0 - unitInterval(bits);
  const double u2 = unitInterval(mix64(bits ^ 0xa54ff53a5f1d36f1ULL));
  constexpr double twoPi = 6.283185307179586476925286766559;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(twoPi * u2);
}

} // namespace detail

double random(std::uint64_t key, std::uint64_t stream) {
  return detail::randomUniform(key, detail::randomStep(), stream);
}

double random_normal(std::uint64_t key, std::uint64_t stream) {
  return detail::randomNormal(key, detail::randomStep(), stream);
}

} // namespace wash
