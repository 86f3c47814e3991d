//===- wash/backend/columns.hpp - structure-of-arrays storage -----*- C++ -*-===//
#pragma once

#include <wash/vec.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

// WASH_OMP(directive) is `#pragma omp directive` in programs built with OpenMP
// (openmp and mpi backends) and nothing in serial ones. The runtime's own
// whole-column loops (reordering, the cell sort) use it:
// left serial, they would cap the OpenMP speed-up (Amdahl) as cores are added.
#if defined(_OPENMP)
#define WASH_OMP_TEXT(...) #__VA_ARGS__
#define WASH_OMP(...) _Pragma(WASH_OMP_TEXT(omp __VA_ARGS__))
#else
#define WASH_OMP(...)
#endif

namespace wash::backend {

/// Those loops run on all threads only from this many elements on (an OpenMP
/// `if` clause). Below it they are cheaper than waking the thread team, which
/// under OMP_WAIT_POLICY=passive costs tens of microseconds a loop: a search
/// runs over a dozen of them, so at a few thousand particles they would make
/// the 2-thread program slower than the 1-thread one.
inline constexpr std::size_t parallelMinimum = 32768;

/// Particle index in the current storage order (which changes when particles
/// are reordered by cell; the id does not).
using Index = std::uint32_t;

/// A value a kernel stores into a float column, already rounded to float,
/// hidden from g++'s optimiser: g++ 12's tree SLP vectoriser would let a read
/// of the column that follows the store use the unrounded double instead
/// (test/e2e/scenes/float_store.cpp; docs/performance.md, "g++ and float
/// storage"). The empty asm only says the value may have changed: no code.
#if defined(__GNUC__) && !defined(__clang__) && (defined(__x86_64__) || defined(__i386__))
#define WASH_OPAQUE(value) asm("" : "+x"(value))
#elif defined(__GNUC__) && !defined(__clang__) && defined(__aarch64__)
#define WASH_OPAQUE(value) asm("" : "+w"(value))
#elif defined(__GNUC__) && !defined(__clang__)
#define WASH_OPAQUE(value) asm("" : "+m"(value))
#else
#define WASH_OPAQUE(value) (void)0
#endif
template <typename T> inline T rounded(T value) {
  WASH_OPAQUE(value);
  return value;
}
template <typename T, int D> inline Vec<T, D> rounded(Vec<T, D> value) {
  if constexpr (sizeof(value) == 8) { // two floats in one register: SLP keeps it one
    WASH_OPAQUE(value);
  } else {
    for (int a = 0; a < D; ++a)
      WASH_OPAQUE(*value[a]);
  }
  return value;
}
#undef WASH_OPAQUE

/// A particle-loop body with nothing to report, as the body of a backend's
/// forEachParticleChecked (whose body returns whether what it wrote is finite).
template <typename Body> auto reportingNothing(Body &body) {
  return [&body](Index i) {
    body(i);
    return true;
  };
}

/// One property of every particle. Plain std::vector: contiguous, and
/// operator[] compiles to a direct array access.
template <typename T> using Column = std::vector<T>;

/// Reorders `column` so that new[k] = old[order[k]]; `order` may also select a
/// subset (the column then shrinks to order.size()). The spare storage is one
/// buffer per element type, shared by all columns of that type and kept between
/// calls: reordering costs one extra column per type, not a copy of everything.
template <typename T> void permute(Column<T> &column, const std::vector<Index> &order) {
  static Column<T> scratch;
  scratch.resize(order.size());
  const std::size_t n = order.size();
  WASH_OMP(parallel for if(n >= parallelMinimum) schedule(static))
  for (std::size_t k = 0; k < n; ++k)
    scratch[k] = column[order[k]];
  column.swap(scratch);
}

/// Removes the rows marked in `gone` by moving rows from the end into the
/// holes: work in proportion to the rows removed, not to all rows (order is
/// not kept; the next cell sort restores it).
template <typename Particles> void removeRows(Particles &P, const std::vector<char> &gone) {
  std::size_t size = P.size();
  for (std::size_t hole = 0; hole < size; ++hole) {
    if (!gone[hole])
      continue;
    while (size > hole + 1 && gone[size - 1])
      --size;
    if (size == hole + 1) {
      size = hole;
      break;
    }
    --size;
    P.forEachColumn([&](auto &column) { column[hole] = column[size]; });
  }
  P.forEachColumn([&](auto &column) { column.resize(size); });
}

/// Keeps only the rows at positions `rows` (any order afterwards).
template <typename Particles> void keepRows(Particles &P, const std::vector<Index> &rows) {
  if (rows.size() == P.size())
    return;
  std::vector<char> gone(P.size(), 1);
  for (Index p : rows)
    gone[p] = 0;
  removeRows(P, gone);
}

/// The columns a neighbour search carries to halo copies (wash/mpi/halo.hpp):
/// `kept` to a copy of a particle the receiving process held a copy of, from
/// the same sender, at the previous search; `fresh` (every column `kept`
/// visits and more) to the others. As a column visitor it visits `fresh`.
template <typename Kept, typename Fresh> struct HaloColumns {
  Kept kept;
  Fresh fresh;
  template <typename F> void operator()(F f) const { fresh(f); }
};

} // namespace wash::backend
