//===- bench/handwritten/ca_fluid_sim.cpp - hand-optimised seed simulation -===//
//
// The performance baseline: examples/ca_fluid_sim/ca_fluid_sim.cpp written by
// hand for speed, computing exactly what the reference build of the seed
// computes (docs/semantics.md), so that its --dump is byte-identical to the
// reference's at any thread count:
//
//  * the same constants, spawn (std::default_random_engine(42)) and kernels:
//    VelocityUpdate; CalculateDensity (force); force_kernel = pressure, then
//    viscosity (force); UpdatePositions; HandleCollisions;
//  * every floating-point expression evaluated in the seed's order (the file is
//    compiled with -ffp-contract=off and without -ffast-math);
//  * neighbours visited in the canonical order: cells of size r anchored at the
//    origin in (y, x) order, x fastest, ids ascending within a cell.
//
// How it is fast:
//  * structure of arrays; every step, after VelocityUpdate (the only kernel that
//    moves `pos`), the particles are reordered by (cell, id) with a parallel
//    counting sort. The storage order then *is* the canonical order, so the
//    neighbour candidates of a particle are one contiguous index range per cell
//    row of its stencil, read straight off the cell-start array.
//  * per particle and per neighbour kernel, one branch-free scan of those
//    candidates builds the particle's neighbour list (index and squared
//    distance) in a per-thread buffer; the particle itself is skipped by
//    splitting its row's range, not tested for. CalculateDensity scans once;
//    force_kernel scans once for both its loops (pressure and viscosity) and
//    computes each neighbour's distance (one sqrt) once for both. There are no
//    stored neighbour lists: one particle's at a time per thread. On a machine
//    with AVX2 (checked at run time, as the generated programs' runtime does)
//    the scan tests four candidates at a time and skips the particle by a lane
//    mask instead.
//  * each loop over the list is split in a "map" pass, which computes every
//    neighbour's terms (sqrt, the six divisions of the pressure force, the
//    kernels' branches as selects) into per-thread arrays with independent
//    iterations that g++ vectorises (SSE2, 2 doubles), and a "reduce" pass that
//    adds the terms in canonical order, as the seed does (never reassociated).
//  * the snapshot rule costs no copy beyond velocity: the reorder gathers the
//    velocities into the snapshot buffer, force_kernel reads neighbours'
//    velocities from it and writes the particle's new velocity to the other
//    buffer (double buffering). Nothing else a neighbour reads is written by
//    force_kernel.
//  * the pressures of the equation of state are computed once per particle at
//    the end of CalculateDensity (same expression, same value) instead of once
//    per neighbour pair;
//  * UpdatePositions and HandleCollisions read and write only their own
//    particle's `position` and `vel`, which no neighbour reads in force_kernel,
//    so they are fused into the end of force_kernel's loop;
//  * mass and smoothing_length are never written after creation: constants.
//  * OpenMP `parallel for` over particles, dynamic schedule, no atomics.
//
// Built with -DHANDWRITTEN_SCALAR_TERMS (target ca_fluid_sim-handwritten-scalar)
// the same program keeps its map passes scalar: g++ may not vectorise the loops
// of calculateDensity and forceTerms. It measures what vectorising the terms
// across neighbours is worth (docs/performance.md).
//
// Options: the wash program options (--steps, --out, --output-every, --format,
// --dump, --quiet, --help; see docs/semantics.md) plus
//   --size N         number of particles (default 4032, the seed's)
//   --box-scale S    scale of spawnSize, spawnCentre and boundsSize
//                    (default sqrt(N / 4032): the seed scene at the same density)
// bench/scenes/make_scaled_seed.sh writes the same scaled scene as a wash program.
//
//===----------------------------------------------------------------------===//
#include <wash/detail/frame.hpp>
#include <wash/detail/options.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/vec.hpp>

#include <omp.h>

#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace {

#if defined(HANDWRITTEN_SCALAR_TERMS)
#define TERMS_LOOPS __attribute__((optimize("no-tree-loop-vectorize")))
#else
#define TERMS_LOOPS
#endif

using wash::Vec2D;
using wash::detail::Column;
using wash::detail::Frame;

// ---- The seed's constants (examples/ca_fluid_sim/ca_fluid_sim.cpp) ----------
constexpr double PI = 3.14159265358979323846;
constexpr double TIME_DELTA(double timeScale, double iterationsPerFrame) {
  return (1.0 / 60.0) / iterationsPerFrame * timeScale;
}
constexpr Vec2D seedSpawnCentre{3.35, 0.51};
constexpr Vec2D initialVelocity{0.0, 0.0};
constexpr Vec2D seedSpawnSize{7.0, 7.0};
constexpr Vec2D seedBoundsSize{17.1, 9.3};
constexpr double jitterStr = 0.025;
constexpr double seedNumParticles = 4032;
constexpr double gravity = -12.0;
constexpr double deltaTime = TIME_DELTA(1, 3);
constexpr double collisionDamping = 0.95;
constexpr double smoothingRadius = 0.35;
constexpr double targetDensity = 55.0;
constexpr double pressureMultiplier = 500.0;
constexpr double nearPressureMultiplier = 18.0;
constexpr double viscosityStrength = 0.06;
constexpr double predictionFactor = 1 / 120.0;

/// The scene: the seed's, or the seed's scaled by `scale` (make_scaled_seed.sh
/// writes these same products, printed exactly, into a copy of the seed).
struct Scene {
  std::size_t numParticles = 4032;
  Vec2D spawnCentre = seedSpawnCentre;
  Vec2D spawnSize = seedSpawnSize;
  Vec2D boundsSize = seedBoundsSize;
};

Scene makeScene(std::size_t n, double scale) {
  Scene s;
  s.numParticles = n;
  s.spawnCentre = Vec2D{seedSpawnCentre.at(0) * scale, seedSpawnCentre.at(1) * scale};
  s.spawnSize = Vec2D{seedSpawnSize.at(0) * scale, seedSpawnSize.at(1) * scale};
  s.boundsSize = Vec2D{seedBoundsSize.at(0) * scale, seedBoundsSize.at(1) * scale};
  return s;
}

// ---- Kernel coefficients: the seed's smoothing kernels with radius = r -------
// The seed writes e.g. `6.0 / (PI * std::pow(radius, 4)) * q * q`, which is
// ((6.0 / (PI * r^4)) * q) * q: the leading constant is one value.
const double r = smoothingRadius;
const double r2 = r * r; // the neighbour test's radius * radius
const double cDensity = 6.0 / (PI * std::pow(smoothingRadius, 4));
const double cNearDensity = 10.0 / (PI * std::pow(smoothingRadius, 5));
const double cDensityDeriv = -12.0 / (PI * std::pow(smoothingRadius, 4));
const double cNearDensityDeriv = -30.0 / (PI * std::pow(smoothingRadius, 5));
const double cViscosity = 4.0 / (PI * std::pow(smoothingRadius, 8));

inline double PressureFromDensity(double density) {
  return (density - targetDensity) * pressureMultiplier;
}
inline double NearPressureFromDensity(double nearDensity) {
  return nearPressureMultiplier * nearDensity;
}

inline std::int64_t cellOf(double x) { return static_cast<std::int64_t>(std::floor(x / r)); }

[[noreturn]] void fail(const std::string &message) {
  std::fflush(stdout);
  std::fprintf(stderr, "ca_fluid_sim-handwritten: error: %s\n", message.c_str());
  std::exit(1);
}

// ---- Particle state, structure of arrays, in (cell, id) order ----------------
struct Particles {
  std::size_t n = 0;
  std::vector<std::uint32_t> id;
  std::vector<double> px, py;   // pos (the predicted position VelocityUpdate sets)
  std::vector<double> vx, vy;   // vel
  std::vector<double> svx, svy; // vel snapshot at the start of force_kernel
  std::vector<double> qx, qy;   // force "position"
  std::vector<double> rho, nrho; // density, force "nearDensity"
  std::vector<double> pres, npres; // PressureFromDensity(rho), NearPressureFromDensity(nrho)
  std::vector<double> fpx, fpy; // force "pressure"
  std::vector<double> fvx, fvy; // force "viscosity"
  // Reorder scratch.
  std::vector<std::uint32_t> id2;
  std::vector<double> px2, py2, qx2, qy2;

  void resize(std::size_t count) {
    n = count;
    for (auto *v : {&id, &id2})
      v->assign(n, 0);
    for (auto *v : {&px, &py, &vx, &vy, &svx, &svy, &qx, &qy, &rho, &nrho, &pres, &npres, &fpx,
                    &fpy, &fvx, &fvy, &px2, &py2, &qx2, &qy2})
      v->assign(n, 0.0);
  }
};

/// The uniform grid of cells of size r over the bounding box of the particles,
/// rows of y, x fastest; cellStart[c] .. cellStart[c + 1] are the (sorted)
/// indices of the particles in cell c.
struct Grid {
  std::int64_t cxmin = 0, cymin = 0, cxmax = -1, cymax = -1, ncx = 0, ncy = 0;
  std::vector<std::uint32_t> cellStart;
  std::vector<std::uint32_t> key;  // cell of each particle (old order)
  std::vector<std::uint32_t> perm; // new index -> old index
  std::vector<std::uint32_t> hist; // per thread, per cell
};

// ---- Spawn: the seed's init(), SpawnParticles ---------------------------------
void spawn(Particles &P, const Scene &scene) {
  const std::size_t particleCount = scene.numParticles;
  std::vector<Vec2D> created;
  created.reserve(particleCount);
  std::uniform_real_distribution<double> unif(0.0, 1.0);
  std::default_random_engine re(42);
  double s_x = scene.spawnSize.at(0);
  double s_y = scene.spawnSize.at(1);
  int numX = (int)std::ceil(
      std::sqrt(s_x / s_y * particleCount + (s_x - s_y) * (s_x - s_y) / (4 * s_y * s_y)) -
      (s_x - s_y) / (2 * s_y));
  int numY = (int)std::ceil((double)particleCount / (double)numX);
  int i = 0;
  for (int y = 0; y < numY; y++) {
    for (int x = 0; x < numX; x++) {
      if (i >= particleCount)
        break;
      double tx = numX <= 1 ? 0.5 : x / (numX - 1.0);
      double ty = numY <= 1 ? 0.5 : y / (numY - 1.0);
      double angle = unif(re) * PI * 2.0;
      Vec2D dir = Vec2D({std::cos(angle), std::sin(angle)});
      Vec2D jitter = dir * jitterStr * (unif(re) - 0.5);
      Vec2D pos = Vec2D({(tx - 0.5) * s_x, (ty - 0.5) * s_y}) + jitter + scene.spawnCentre;
      created.push_back(pos);
      if (i < 5)
        std::cout << "Particle " << i << " position " << pos << std::endl;
      i++;
    }
  }
  P.resize(created.size());
  for (std::size_t k = 0; k < created.size(); ++k) {
    P.id[k] = std::uint32_t(k);
    P.px[k] = P.qx[k] = created[k].at(0); // create_particle(pos); set "position" = pos
    P.py[k] = P.qy[k] = created[k].at(1);
    P.vx[k] = initialVelocity.at(0);
    P.vy[k] = initialVelocity.at(1);
  }
}

// ---- One step ----------------------------------------------------------------

/// VelocityUpdate, then the reorder by (cell, id) of everything a later kernel
/// of this step or a later step reads (id, pos, vel -> snapshot, position).
/// Returns false if a position is not finite.
bool velocityUpdateAndReorder(Particles &P, Grid &G, std::uint64_t step) {
  const std::size_t n = P.n;
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  bool finite = true;
  double *vx = P.vx.data(), *vy = P.vy.data(), *px = P.px.data(), *py = P.py.data();
  const double *qx = P.qx.data(), *qy = P.qy.data();
  const double gx = 0.0 * deltaTime, gy = gravity * deltaTime; // ExternelForces(...) * deltaTime
#pragma omp parallel for schedule(static) reduction(min : xmin, ymin) reduction(max : xmax, ymax) reduction(&& : finite)
  for (std::size_t i = 0; i < n; ++i) {
    // VelocityUpdate
    double nvx = vx[i] + gx, nvy = vy[i] + gy;
    vx[i] = nvx;
    vy[i] = nvy;
    double x = qx[i] + nvx * predictionFactor, y = qy[i] + nvy * predictionFactor;
    px[i] = x;
    py[i] = y;
    finite = finite && std::isfinite(x) && std::isfinite(y);
    xmin = std::min(xmin, x);
    xmax = std::max(xmax, x);
    ymin = std::min(ymin, y);
    ymax = std::max(ymax, y);
  }
  if (!finite) {
    std::fprintf(stderr, "step %llu: after kernel 'VelocityUpdate': a position is not finite\n",
                 (unsigned long long)step);
    return false;
  }
  if (n == 0)
    return true;
  // floor(x / r) is monotone in x, so the cells of the extremes bound all cells.
  G.cxmin = cellOf(xmin);
  G.cxmax = cellOf(xmax);
  G.cymin = cellOf(ymin);
  G.cymax = cellOf(ymax);
  G.ncx = G.cxmax - G.cxmin + 1;
  G.ncy = G.cymax - G.cymin + 1;
  const double cells = double(G.ncx) * double(G.ncy);
  if (cells > 64.0 * double(n) + double(1 << 22))
    fail("step " + std::to_string(step) + ": particles spread over too many cells (" +
         std::to_string(cells) + ") for the dense grid");
  const std::size_t ncells = std::size_t(G.ncx * G.ncy);
  const int nthreads = omp_get_max_threads();
  G.cellStart.assign(ncells + 1, 0);
  G.key.resize(n);
  G.perm.resize(n);
  G.hist.assign(ncells * std::size_t(nthreads), 0);
  std::uint32_t *key = G.key.data(), *perm = G.perm.data(), *hist = G.hist.data(),
                *cellStart = G.cellStart.data();
  const std::uint32_t *id = P.id.data();

  // Counting sort by cell: per-thread histograms of fixed chunks, so no atomics.
#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num(), T = omp_get_num_threads();
    const std::size_t begin = n * t / T, end = n * (t + 1) / T;
    std::uint32_t *h = hist + std::size_t(t) * ncells;
    for (std::size_t i = begin; i < end; ++i) {
      std::uint32_t k =
          std::uint32_t((cellOf(py[i]) - G.cymin) * G.ncx + (cellOf(px[i]) - G.cxmin));
      key[i] = k;
      ++h[k];
    }
#pragma omp barrier
#pragma omp single
    {
      std::uint32_t running = 0;
      for (std::size_t c = 0; c < ncells; ++c) {
        cellStart[c] = running;
        for (int u = 0; u < T; ++u) {
          std::uint32_t count = hist[std::size_t(u) * ncells + c];
          hist[std::size_t(u) * ncells + c] = running;
          running += count;
        }
      }
      cellStart[ncells] = running;
    } // implicit barrier
    for (std::size_t i = begin; i < end; ++i)
      perm[h[key[i]]++] = std::uint32_t(i);
#pragma omp barrier
    // Ids ascending within each cell. The members arrive as a few sorted runs
    // (one per cell they came from), so insertion sort is the right tool.
#pragma omp for schedule(dynamic, 256)
    for (std::size_t c = 0; c < ncells; ++c) {
      const std::uint32_t b = cellStart[c], e = cellStart[c + 1];
      for (std::uint32_t a = b + 1; a < e; ++a) {
        std::uint32_t v = perm[a], vid = id[v], z = a;
        while (z > b && id[perm[z - 1]] > vid) {
          perm[z] = perm[z - 1];
          --z;
        }
        perm[z] = v;
      }
    }
    // Gather into the new order; velocities go to the snapshot buffer.
    std::uint32_t *id2 = P.id2.data();
    double *px2 = P.px2.data(), *py2 = P.py2.data(), *qx2 = P.qx2.data(), *qy2 = P.qy2.data(),
           *svx = P.svx.data(), *svy = P.svy.data();
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t o = perm[k];
      id2[k] = id[o];
      px2[k] = px[o];
      py2[k] = py[o];
      qx2[k] = qx[o];
      qy2[k] = qy[o];
      svx[k] = vx[o];
      svy[k] = vy[o];
    }
  }
  P.id.swap(P.id2);
  P.px.swap(P.px2);
  P.py.swap(P.py2);
  P.qx.swap(P.qx2);
  P.qy.swap(P.qy2);
  return true;
}

/// Calls f(begin, end) for each cell row of the stencil of (x, y): the
/// candidates of that row, in canonical order. The stencil is computed from the
/// interval [p - r, p + r] as the reference's cell list does.
template <typename F> inline void forEachStencilRow(const Grid &G, double x, double y, F &&f) {
  std::int64_t lox = std::max(cellOf(x - r), G.cxmin), hix = std::min(cellOf(x + r), G.cxmax);
  std::int64_t loy = std::max(cellOf(y - r), G.cymin), hiy = std::min(cellOf(y + r), G.cymax);
  if (lox > hix)
    return;
  const std::uint32_t *cs = G.cellStart.data();
  for (std::int64_t cy = loy; cy <= hiy; ++cy) {
    const std::int64_t row = (cy - G.cymin) * G.ncx - G.cxmin;
    f(cs[row + lox], cs[row + hix + 1]);
  }
}

// ---- Neighbour lists: one particle, one kernel ----------------------------------
// A kernel's work for particle i starts by scanning the candidates of its
// stencil (one contiguous index range per cell row, in canonical order) once,
// and keeping, without branches (the test's outcome is random, a branch on it
// mispredicts), the neighbours: their index and squared distance. The list lives in a per-thread buffer for one particle at a time;
// there are no stored neighbour lists. Every loop of the kernel then runs over
// that short list in two passes: a "map" pass computing each neighbour's terms
// into arrays (independent iterations: g++ vectorises it, sqrt and divisions
// included) and a "reduce" pass adding them up in canonical order (the order
// the seed adds them in: the sums are never reassociated).
struct NeighbourList {
  std::vector<std::uint64_t> j; // 64-bit: g++ then vectorises the map loops with doubles
  std::vector<double> dist; // squared distances from the scan, then distances
  std::vector<double> t0, t1, t2, t3, t4; // per-neighbour terms (map pass)
  void ensure(std::size_t m) {
    if (j.size() >= m)
      return;
    m += m / 2 + 64;
    j.resize(m);
    for (auto *v : {&dist, &t0, &t1, &t2, &t3, &t4})
      v->resize(m);
  }
};

/// The candidate ranges of the stencil of (x, y): at most kMaxRows cell rows.
constexpr int kMaxRows = 4;
struct Rows {
  int count = 0;
  std::uint32_t b[kMaxRows], e[kMaxRows];
  std::size_t total = 0;
};

inline void stencilRows(const Grid &G, double x, double y, Rows &R) {
  R.count = 0;
  R.total = 0;
  forEachStencilRow(G, x, y, [&](std::uint32_t b, std::uint32_t e) {
    if (R.count == kMaxRows) // cannot happen with cells of size r; stay safe
      fail("stencil with more than 4 cell rows");
    R.b[R.count] = b;
    R.e[R.count] = e;
    ++R.count;
    R.total += e - b;
  });
}

/// Appends to the list the candidates [b, e) within the radius of (x, y):
/// their squared distance and, if WithIndex, their index. Branch-free: the
/// entry is always written, and kept (the count advanced) if it passes the
/// test. (A two-lane SSE2 version of this loop was no faster; on AVX2
/// machines scanRowsAvx2 below replaces it.)
template <bool WithIndex>
inline std::uint32_t scanRange(const double *__restrict px, const double *__restrict py, double x,
                               double y, std::uint32_t b, std::uint32_t e,
                               std::uint64_t *__restrict jout, double *__restrict d2out,
                               std::uint32_t m) {
  for (std::uint32_t j = b; j < e; ++j) {
    const double ox = px[j] - x, oy = py[j] - y;
    const double d2 = ox * ox + oy * oy; // withinRadius: (0 + dx*dx) + dy*dy, 0 + a == a here
    d2out[m] = d2;
    if constexpr (WithIndex)
      jout[m] = j;
    m += std::uint32_t(d2 <= r2);
  }
  return m;
}

#if defined(__GNUC__) && defined(__x86_64__)
#define HANDWRITTEN_AVX2 1
/// Whether this machine runs AVX2 code. The program is built for baseline
/// x86-64 like every wash program; the scan takes the AVX2 path at run time,
/// as the generated programs' runtime does (backends/.../scan_avx2.hpp).
bool hasAvx2() {
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
}

/// Per 4-bit mask of kept lanes, the 32-bit lanes that bring the kept 64-bit
/// values to the front in order.
struct KeptFirst {
  alignas(32) std::int32_t lanes[16][8] = {};
  KeptFirst() {
    for (int mask = 0; mask < 16; ++mask)
      for (int lane = 0, next = 0; lane < 4; ++lane)
        if (mask & (1 << lane)) {
          lanes[mask][next++] = 2 * lane;
          lanes[mask][next++] = 2 * lane + 1;
        }
  }
};
const KeptFirst keptFirst;

/// scanRange over every stencil row, four candidates an iteration, leaving
/// out particle i and the entries past a row's end by one vector mask instead
/// of splitting rows. A block may read up to three entries past a row's end (n
/// bounds that); the same d2 = dx*dx + dy*dy. One call per particle.
template <bool WithIndex>
__attribute__((target("avx2"))) std::uint32_t
scanRowsAvx2(const double *__restrict px, const double *__restrict py, std::size_t n, double x,
             double y, const Rows &R, std::uint32_t i, std::uint64_t *__restrict jout,
             double *__restrict d2out) {
  const __m256d cx = _mm256_set1_pd(x), cy = _mm256_set1_pd(y), limit = _mm256_set1_pd(r2);
  const __m256i self = _mm256_set1_epi64x(i), four = _mm256_set1_epi64x(4);
  std::uint32_t m = 0;
  for (int row = 0; row < R.count; ++row) {
    const std::uint32_t b = R.b[row], e = R.e[row];
    const __m256i end = _mm256_set1_epi64x(e);
    __m256i index = _mm256_add_epi64(_mm256_set1_epi64x(b), _mm256_setr_epi64x(0, 1, 2, 3));
    std::uint32_t j = b;
    for (; j < e && j + 4 <= n; j += 4, index = _mm256_add_epi64(index, four)) {
      const __m256d ox = _mm256_sub_pd(_mm256_loadu_pd(px + j), cx);
      const __m256d oy = _mm256_sub_pd(_mm256_loadu_pd(py + j), cy);
      const __m256d d2 = _mm256_add_pd(_mm256_mul_pd(ox, ox), _mm256_mul_pd(oy, oy));
      const __m256i near = _mm256_castpd_si256(_mm256_cmp_pd(d2, limit, _CMP_LE_OQ));
      const __m256i keep = _mm256_andnot_si256(
          _mm256_cmpeq_epi64(index, self), _mm256_and_si256(near, _mm256_cmpgt_epi64(end, index)));
      const int kept = _mm256_movemask_pd(_mm256_castsi256_pd(keep));
      const __m256i front =
          _mm256_load_si256(reinterpret_cast<const __m256i *>(keptFirst.lanes[kept]));
      _mm256_storeu_pd(d2out + m, _mm256_castsi256_pd(
                                      _mm256_permutevar8x32_epi32(_mm256_castpd_si256(d2), front)));
      if constexpr (WithIndex)
        _mm256_storeu_si256(reinterpret_cast<__m256i *>(jout + m),
                            _mm256_permutevar8x32_epi32(index, front));
      m += std::uint32_t(__builtin_popcount(unsigned(kept)));
    }
    for (; j < e; ++j) { // the column's last few
      const double ox = px[j] - x, oy = py[j] - y;
      const double d2 = ox * ox + oy * oy;
      d2out[m] = d2;
      if constexpr (WithIndex)
        jout[m] = j;
      m += std::uint32_t(d2 <= r2 && j != i);
    }
  }
  return m;
}

/// The distances of the m neighbours kept: sqrt of their squared distances in
/// place, four at a time (the list has room for a whole last block).
__attribute__((target("avx2"))) void distancesAvx2(double *d, std::uint32_t m) {
  for (std::uint32_t k = 0; k < m; k += 4)
    _mm256_storeu_pd(d + k, _mm256_sqrt_pd(_mm256_loadu_pd(d + k)));
}
#else
#define HANDWRITTEN_AVX2 0
#endif

/// The neighbours of particle i, in canonical order: distances (sqrt of the
/// squared distances the test computed: `offset.magnitude()`, bit for bit)
/// and, if WithIndex, indices (the density needs no more than the distances;
/// the force kernels recompute the offsets, an exact subtraction, from the
/// indices).
template <bool WithIndex>
inline std::uint32_t listNeighbours(const Grid &G, const double *px, const double *py,
                                    std::size_t n, std::uint32_t i, NeighbourList &L) {
  const double x = px[i], y = py[i];
  Rows R;
  stencilRows(G, x, y, R);
  L.ensure(R.total);
  std::uint32_t m = 0;
  std::uint64_t *jout = L.j.data();
  double *d2out = L.dist.data();
#if HANDWRITTEN_AVX2
  if (hasAvx2()) {
    m = scanRowsAvx2<WithIndex>(px, py, n, x, y, R, i, jout, d2out);
    distancesAvx2(d2out, m);
    return m;
  }
#endif
  for (int row = 0; row < R.count; ++row) {
    const std::uint32_t b = R.b[row], e = R.e[row];
    if (b <= i && i < e) { // the particle itself: skipped by splitting the range
      m = scanRange<WithIndex>(px, py, x, y, b, i, jout, d2out, m);
      m = scanRange<WithIndex>(px, py, x, y, i + 1, e, jout, d2out, m);
    } else {
      m = scanRange<WithIndex>(px, py, x, y, b, e, jout, d2out, m);
    }
  }
  for (std::uint32_t k = 0; k < m; ++k)
    d2out[k] = std::sqrt(d2out[k]);
  return m;
}

/// Particles per dynamic chunk of the neighbour loops: 64, or a 64th of a
/// thread's share when that is more, as the generated code's (wash/openmp/
/// for_each.hpp): with small chunks every thread pulls all rows of cells into
/// its own cache, which at a million particles they outgrow.
std::size_t chunkFor(std::size_t n) {
  return std::max<std::size_t>(64, n / (64 * std::size_t(omp_get_max_threads())));
}

/// CalculateDensity, plus the per-particle pressures the pressure force reads.
TERMS_LOOPS void calculateDensity(Particles &P, const Grid &G) {
  const std::size_t n = P.n;
  const double *px = P.px.data(), *py = P.py.data();
  double *rho = P.rho.data(), *nrho = P.nrho.data(), *pres = P.pres.data(),
         *npres = P.npres.data();
#pragma omp parallel
  {
    NeighbourList L;
#pragma omp for schedule(dynamic, chunkFor(n))
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t m = listNeighbours<false>(G, px, py, n, std::uint32_t(i), L);
      const double *dist = L.dist.data();
      double *dk = L.t0.data(), *ndk = L.t1.data();
      for (std::uint32_t k = 0; k < m; ++k) { // map
        const double dst = dist[k];           // offset.magnitude(), from the scan
        const double q = r - dst;
        const bool in = !(dst >= r);
        dk[k] = in ? cDensity * q * q : 0.0;        // DensityKernel
        ndk[k] = in ? cNearDensity * q * q * q : 0.0; // NearDensityKernel
      }
      double density = 1.0;
      double nearDensity = 1.0;
      for (std::uint32_t k = 0; k < m; ++k) { // reduce, in canonical order
        density += dk[k];
        nearDensity += ndk[k];
      }
      rho[i] = density;
      nrho[i] = nearDensity;
      pres[i] = PressureFromDensity(density);
      npres[i] = NearPressureFromDensity(nearDensity);
    }
  }
}

/// The terms of each neighbour in force_kernel (independent: vectorised).
TERMS_LOOPS inline void forceTerms(std::uint32_t m, const std::uint64_t *__restrict nj,
                                   const double *__restrict px, const double *__restrict py,
                                   const double x, const double y, const double *__restrict ndist,
                                   const double *__restrict rho, const double *__restrict nrho,
                                   const double *__restrict pres, const double *__restrict npres,
                                   const double pressure, const double nearPressure,
                                   double *__restrict tx1, double *__restrict ty1,
                                   double *__restrict tx2, double *__restrict ty2,
                                   double *__restrict tw) {
  for (std::uint32_t k = 0; k < m; ++k) {
    const std::uint64_t j = nj[k];
    const double ox = px[j] - x, oy = py[j] - y; // offsetToNeighbour
    const double dst = ndist[k]; // from the scan
    const bool pos = dst > 0.0;
    const double dirx = pos ? ox / dst : 0.0;
    const double diry = pos ? oy / dst : 1.0;
    const bool in = !(dst >= r);
    const double q = r - dst;
    const double dd = in ? cDensityDeriv * q : 0.0;          // DensityDerivative
    const double ndd = in ? cNearDensityDeriv * q * q : 0.0; // NearDensityDerivative
    const double sharedPressure = (pressure + pres[j]) * 0.5;
    const double sharedNearPressure = (nearPressure + npres[j]) * 0.5;
    const double neighbourDensity = rho[j];
    const double neighbourNearDensity = nrho[j];
    tx1[k] = dirx * dd * sharedPressure / neighbourDensity;
    ty1[k] = diry * dd * sharedPressure / neighbourDensity;
    tx2[k] = dirx * ndd * sharedNearPressure / neighbourNearDensity;
    ty2[k] = diry * ndd * sharedNearPressure / neighbourNearDensity;
    const double v = r * r - dst * dst;
    tw[k] = in ? cViscosity * v * v * v : 0.0; // ViscosityKernel
  }
}

/// force_kernel (CalculatePressureForce, then CalculateViscosity), then the
/// update kernels UpdatePositions and HandleCollisions of the same particle.
/// One neighbour list serves both loops of force_kernel; the distance (one
/// sqrt) is computed once per neighbour and used by both.
void forceAndUpdate(Particles &P, const Grid &G, const Scene &scene) {
  const std::size_t n = P.n;
  const double *px = P.px.data(), *py = P.py.data(), *rho = P.rho.data(),
               *nrho = P.nrho.data(), *pres = P.pres.data(), *npres = P.npres.data(),
               *svx = P.svx.data(), *svy = P.svy.data();
  double *vx = P.vx.data(), *vy = P.vy.data(), *qx = P.qx.data(), *qy = P.qy.data(),
         *fpx = P.fpx.data(), *fpy = P.fpy.data(), *fvx = P.fvx.data(), *fvy = P.fvy.data();
  const double halfX = scene.boundsSize.at(0) * 0.5, halfY = scene.boundsSize.at(1) * 0.5;
#pragma omp parallel
  {
    NeighbourList L;
#pragma omp for schedule(dynamic, chunkFor(n))
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t m = listNeighbours<true>(G, px, py, n, std::uint32_t(i), L);
      const std::uint64_t *__restrict nj = L.j.data();
      const double *__restrict ndist = L.dist.data();
      double *__restrict tx1 = L.t0.data(), *__restrict ty1 = L.t1.data(),
             *__restrict tx2 = L.t2.data(), *__restrict ty2 = L.t3.data(),
             *__restrict tw = L.t4.data();
      // CalculatePressureForce (and the viscosity kernel's weights): map.
      const double density = rho[i];
      forceTerms(m, nj, px, py, px[i], py[i], ndist, rho, nrho, pres, npres, pres[i], npres[i], tx1, ty1, tx2,
                 ty2, tw);
      // ... reduce, in canonical order.
      double pfx = 0.0, pfy = 0.0;
      for (std::uint32_t k = 0; k < m; ++k) {
        pfx += tx1[k];
        pfy += ty1[k];
        pfx += tx2[k];
        pfy += ty2[k];
      }
      const double ax = pfx / density, ay = pfy / density;
      fpx[i] = pfx / density;
      fpy[i] = pfy / density;
      const double velx = svx[i] + ax * deltaTime, vely = svy[i] + ay * deltaTime;
      // CalculateViscosity: neighbours' velocities from the snapshot, own updated.
      double vfx = 0.0, vfy = 0.0;
      for (std::uint32_t k = 0; k < m; ++k) {
        const std::uint64_t j = nj[k];
        vfx += (svx[j] - velx) * tw[k];
        vfy += (svy[j] - vely) * tw[k];
      }
      fvx[i] = vfx * viscosityStrength;
      fvy[i] = vfy * viscosityStrength;
      double nvx = velx + vfx * viscosityStrength * deltaTime;
      double nvy = vely + vfy * viscosityStrength * deltaTime;
      // UpdatePositions
      double posx = qx[i] + nvx * deltaTime, posy = qy[i] + nvy * deltaTime;
      // HandleCollisions
      const double edgeX = halfX - (posx < 0.0 ? -posx : posx);
      const double edgeY = halfY - (posy < 0.0 ? -posy : posy);
      if (edgeX <= 0) {
        posx = halfX * wash::sgn(posx);
        nvx *= -1 * collisionDamping;
      }
      if (edgeY <= 0) {
        posy = halfY * wash::sgn(posy);
        nvy *= -1 * collisionDamping;
      }
      qx[i] = posx;
      qy[i] = posy;
      vx[i] = nvx;
      vy[i] = nvy;
    }
  }
}

/// The state as the reference's Frame: id, pos, vel, acc, density, mass,
/// smoothing_length, then nearDensity, predictedPosition, pressure (add_force
/// order), then position, viscosity (created on first use, by name). Rows in id
/// order, as the reference stores them, so that VTK frames (written in row
/// order) are identical too, not only the CSV (sorted by id by the writer).
Frame makeFrame(const Particles &P, bool viscosityCreated) {
  const std::size_t n = P.n;
  Frame f;
  f.dimensions = 2;
  f.ids.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    f.ids[i] = i;
  auto vec = [&](const char *name, const std::vector<double> &a, const std::vector<double> &b) {
    Column c{name, 2, std::vector<double>(2 * n)};
    for (std::size_t i = 0; i < n; ++i) {
      c.values[2 * std::size_t(P.id[i])] = a[i];
      c.values[2 * std::size_t(P.id[i]) + 1] = b[i];
    }
    f.columns.push_back(std::move(c));
  };
  auto scalar = [&](const char *name, const std::vector<double> &a) {
    Column c{name, 1, std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i)
      c.values[P.id[i]] = a[i];
    f.columns.push_back(std::move(c));
  };
  vec("pos", P.px, P.py);
  vec("vel", P.vx, P.vy);
  // The seed never sets acc: zeros, in frames only, as the reference writes.
  f.columns.push_back(Column{"acc", 2, std::vector<double>(2 * n, 0.0), /*inDump=*/false});
  scalar("density", P.rho);
  f.columns.push_back(Column{"mass", 1, std::vector<double>(n, 1.0)});
  f.columns.push_back(Column{"smoothing_length", 1, std::vector<double>(n, smoothingRadius)});
  scalar("nearDensity", P.nrho);
  f.columns.push_back(Column{"predictedPosition", 2, std::vector<double>(2 * n, 0.0)});
  vec("pressure", P.fpx, P.fpy);
  vec("position", P.qx, P.qy);
  if (viscosityCreated)
    vec("viscosity", P.fvx, P.fvy);
  return f;
}

bool parseSize(const std::string &text, std::size_t &out) {
  char *end = nullptr;
  unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || *end || text[0] == '-' || v > 0xFFFFFFFFull)
    return false;
  out = std::size_t(v);
  return true;
}

int run(int argc, char **argv) {
  const std::string program = argc > 0 ? argv[0] : "ca_fluid_sim-handwritten";
  // Our own scene options first; the rest are the wash program options.
  std::size_t size = std::size_t(seedNumParticles);
  double boxScale = -1.0;
  std::vector<char *> rest;
  for (int i = 0; i < argc; ++i) {
    std::string a = argv[i];
    std::string name = a, value;
    bool hasValue = false;
    if (auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
      name = a.substr(0, eq);
      value = a.substr(eq + 1);
      hasValue = true;
    }
    if (i > 0 && (name == "--size" || name == "--box-scale")) {
      if (!hasValue) {
        if (i + 1 >= argc) {
          std::fprintf(stderr, "%s: error: option '%s' expects a value\n", program.c_str(),
                       name.c_str());
          return 2;
        }
        value = argv[++i];
      }
      if (name == "--size") {
        if (!parseSize(value, size)) {
          std::fprintf(stderr, "%s: error: option '--size' expects a particle count, got '%s'\n",
                       program.c_str(), value.c_str());
          return 2;
        }
      } else {
        char *end = nullptr;
        boxScale = std::strtod(value.c_str(), &end);
        if (value.empty() || *end || !(boxScale > 0.0) || !std::isfinite(boxScale)) {
          std::fprintf(stderr, "%s: error: option '--box-scale' expects a positive number, got '%s'\n",
                       program.c_str(), value.c_str());
          return 2;
        }
      }
      continue;
    }
    rest.push_back(argv[i]);
  }
  wash::detail::ParsedArgs parsed;
  try {
    parsed = wash::detail::parseProgramOptions(int(rest.size()), rest.data());
  } catch (const wash::detail::OptionError &e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 2;
  }
  const auto &opt = parsed.options;
  if (opt.help) {
    std::fputs(wash::detail::usageText(program).c_str(), stdout);
    std::fputs("hand-written options:\n"
               "  --size N           number of particles (default 4032)\n"
               "  --box-scale S      scale of the spawn box, its centre and the bounds\n"
               "                     (default sqrt(N / 4032): the seed's density)\n",
               stdout);
    return 0;
  }
  if (boxScale < 0.0)
    boxScale = std::sqrt(double(size) / seedNumParticles);
  const Scene scene = makeScene(size, boxScale);
  // The seed's main: argv[1] names the simulation, argv[2] the output files.
  const auto &user = parsed.userArgv; // null-terminated
  std::string simulationName = user.size() > 2 ? user[1] : "serial_test";
  std::string baseName = user.size() > 3 ? user[2] : simulationName;
  const std::uint64_t steps = opt.steps ? *opt.steps : 1000;

  try {
    wash::detail::RunOutput output(opt, baseName);
    Particles P;
    Grid G;
    std::cout << "Calculated Time Step: " << deltaTime << std::endl;
    spawn(P, scene);
    const bool talk = !opt.quiet;
    if (talk)
      std::printf("wash handwritten: '%s', %zu particles, 2D, double, influence radius %g, %llu "
                  "steps, %d threads, box scale %.17g\n",
                  simulationName.c_str(), P.n, smoothingRadius, (unsigned long long)steps,
                  omp_get_max_threads(), boxScale);
    std::fflush(stdout);
    if (output.frameDue(0, steps))
      output.writeFrame(0, makeFrame(P, false), /*time=*/0.0);
    auto t0 = std::chrono::steady_clock::now();
    for (std::uint64_t step = 1; step <= steps; ++step) {
      if (!velocityUpdateAndReorder(P, G, step))
        return 1;
      calculateDensity(P, G);
      forceAndUpdate(P, G, scene);
      if (output.frameDue(step, steps))
        output.writeFrame(step, makeFrame(P, true), /*time=*/0.0);
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    Frame last = makeFrame(P, steps > 0);
    std::string bad = wash::detail::findNonFinite(last);
    if (!bad.empty())
      fail("after step " + std::to_string(steps) + ": " + bad);
    output.finish(last);
    if (talk)
      std::printf("wash: %llu steps of %zu particles in %.3f s (%.3g particle-steps/s, %.1f ns "
                  "per particle-step); output in %s\n",
                  (unsigned long long)steps, P.n, seconds,
                  seconds > 0 ? double(steps) * double(P.n) / seconds : 0.0,
                  steps && P.n ? seconds * 1e9 / (double(steps) * double(P.n)) : 0.0,
                  output.directory().c_str());
  } catch (const std::exception &e) {
    fail(e.what());
  }
  return 0;
}

} // namespace

int main(int argc, char **argv) { return run(argc, argv); }
