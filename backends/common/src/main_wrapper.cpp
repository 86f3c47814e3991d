//===- main_wrapper.cpp - the entry point of generated programs --------===//
//
// Generated programs link with -Wl,--wrap=main, as reference programs do.
//
//===----------------------------------------------------------------------===//
#include <wash/backend/thread_waiting.hpp>
#include <wash/detail/entry.hpp>
#include <wash/detail/hdf5_series.hpp>

extern "C" int __real_main(int argc, char **argv);
extern "C" int __wrap_main(int argc, char **argv) {
  wash::backend::boundThreadWaiting(argv);
  wash::detail::hdf5Opener() = &wash::detail::openSerialHdf5Series;
  return wash::detail::runProgram(argc, argv, &__real_main);
}
