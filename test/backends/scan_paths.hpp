// Runs a check on every path the neighbour scan can take on this machine.
#pragma once

#include <wash/backend/scan_avx2.hpp>

#include <gtest/gtest.h>

namespace wash::backend {

/// Runs check() with the scalar scan, then with the AVX2 one where the
/// machine has it (scan_avx2.hpp): both must give the reference's lists.
template <typename Check> inline void onEveryScanPath(Check check) {
#if WASH_SCAN_AVX2
  const bool saved = avx2Scan();
  avx2Scan() = false;
  {
    SCOPED_TRACE("scalar scan");
    check();
  }
  if (cpuHasAvx2()) {
    avx2Scan() = true;
    SCOPED_TRACE("AVX2 scan");
    check();
  }
  avx2Scan() = saved;
#else
  check();
#endif
}

} // namespace wash::backend
