//===- wash/backend/thread_waiting.hpp - threads that wait, sleep -*- C++ -*-===//
//
// An OpenMP thread that runs out of work spins for the next parallel region:
// libgomp's default is 300,000 spins (milliseconds), libomp's 200 ms. On a
// machine whose cores are busy with other processes that spinning takes the
// core from the thread it waits for: the seed at 2 threads beside one busy
// process ran 4-10 times slower than at 1 (docs/performance.md, "Threads on a
// shared machine"). On idle cores the spin pays: bounded to 1000 spins, the
// seed at 2 threads ran 24-60 % slower and the dam break 20-170 % (the
// threads sleep between kernels and take a wake-up each region). So the
// bound is the user's choice, WASH_SHARED_MACHINE=1, which the summary line's
// warning names when the cores were busy. The OpenMP
// runtime reads its settings once, in its own constructor, before any of the
// program's code runs (and .preinit_array runs before libc has set up the
// environment, so a setenv there is lost): the entry point sets them and
// executes the program again, once, on the first thread of main. A setting
// the user gave (OMP_WAIT_POLICY, GOMP_SPINCOUNT) is kept and nothing is
// executed again; one thread never waits, so neither is it then, nor under
// valgrind (which would not follow). A debugger follows the second start.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/profile.hpp>

#include <cstdlib>
#include <cstring>

#include <unistd.h>

namespace wash::backend {

/// libgomp: spin about as long as a short serial stretch between two
/// kernels lasts (tens of microseconds), then sleep.
inline constexpr const char *gompSpinCount = "1000";

/// Called first thing in main: returns only when the OpenMP runtime already
/// runs with the user's settings or the bounded spin (or if executing again
/// failed: the program then runs as it would have).
inline void boundThreadWaiting(char **argv) {
  const char *shared = std::getenv("WASH_SHARED_MACHINE");
  if (!shared || !*shared || std::strcmp(shared, "0") == 0 || detail::loopThreads < 2 ||
      std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT"))
    return;
  setenv("GOMP_SPINCOUNT", gompSpinCount, /*overwrite=*/1);
  setenv("KMP_BLOCKTIME", "0", /*overwrite=*/0); // libomp (clang): sleep at once
  // Under valgrind the program executed again would run without it.
  const char *preloaded = std::getenv("LD_PRELOAD");
  if (preloaded && std::strstr(preloaded, "vgpreload"))
    return;
  execv("/proc/self/exe", argv);
}

} // namespace wash::backend
