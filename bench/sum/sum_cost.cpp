// sum_cost - the per-particle cost of a Sum reduction: the exact sum every
// runtime does now (wash::detail::ExactSum) beside the ordered sum it
// replaced (values scattered into id order, then added one by one), over the
// same values in one run, and the plain adds of an ordered sum without the
// scatter (what the accumulator itself costs over a double add). Rounds are interleaved and each
// method's fastest round is kept, so the machine's drift hits all alike.
//
//   sum_cost [N] [ROUNDS]    N values (default 1048576), ROUNDS (default 7)
//
// The values are what a reduction kernel returns over particles in cell
// order: ids a permutation of 0..N-1, values of mixed sign and magnitude.
// Nothing is asserted: speed is measured, never tested.
#include <wash/backend/reduce.hpp>
#include <wash/openmp/for_each.hpp>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <vector>

using wash::backend::Index;

namespace {

/// The Sum before exact sums (backend/reduce.hpp and detail/reduction.hpp
/// at 5d5ce76): values into id order, then added from 0 in that order.
double orderedSum(const std::vector<std::uint64_t> &ids, const std::vector<double> &values,
                  const std::vector<Index> &rows) {
  std::vector<double> byId(rows.size());
  for (Index p : rows)
    byId[ids[p]] = values[p];
  double r = 0.0;
  for (double v : byId)
    r += v;
  return r;
}

template <typename F> double seconds(F f, double &result) {
  const auto start = std::chrono::steady_clock::now();
  result = f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

int main(int argc, char **argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1048576;
  const int rounds = argc > 2 ? std::atoi(argv[2]) : 7;
  std::mt19937_64 random(21);
  std::vector<std::uint64_t> ids(n);
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), random);
  std::vector<double> values(n);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (double &v : values)
    v = std::ldexp(unit(random), int(random() % 40) - 20);
  std::vector<Index> rows(n);
  std::iota(rows.begin(), rows.end(), Index(0));

  struct Method {
    const char *name;
    double best = 1e30, result = 0;
  } methods[] = {{"ordered (the old Sum: id order, then one by one)"},
                 {"ordered adds alone (values already in id order)"},
                 {"exact, one thread (reference, serial backend)"},
                 {"exact, OpenMP threads merged"}};
  std::vector<double> byId(n);
  for (Index p : rows)
    byId[ids[p]] = values[p];
  for (int r = 0; r < rounds; ++r) {
    double t[4];
    t[0] = seconds([&] { return orderedSum(ids, values, rows); }, methods[0].result);
    t[1] =
        seconds([&] { return std::accumulate(byId.begin(), byId.end(), 0.0); }, methods[1].result);
    t[2] = seconds([&] { return wash::backend::sumRows(values, rows).round<double>(); },
                   methods[2].result);
    t[3] = seconds([&] { return wash::openmp::Loop::sum(values, rows).round<double>(); },
                   methods[3].result);
    for (int m = 0; m < 4; ++m)
      methods[m].best = std::min(methods[m].best, t[m]);
  }
  std::printf("%zu values, fastest of %d rounds, OpenMP threads: %d\n", n, rounds,
              omp_get_max_threads());
  std::printf("%-50s %12s %14s %s\n", "method", "ns/value", "ratio to old", "result");
  for (const Method &m : methods)
    std::printf("%-50s %12.2f %14.2f %a\n", m.name, 1e9 * m.best / double(n),
                m.best / methods[0].best, m.result);
  return methods[2].result == methods[3].result ? 0 : 1; // exact: the same bits
}
