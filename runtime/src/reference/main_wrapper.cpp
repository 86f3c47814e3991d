//===- main_wrapper.cpp - the entry point of reference programs ---------===//
//
// The wash targets link with -Wl,--wrap=main, so the program starts here.
// Kept apart from the runtime so that unit tests can link the runtime alone.
//
//===----------------------------------------------------------------------===//
#include <wash/detail/entry.hpp>
#include <wash/detail/hdf5_series.hpp>

extern "C" int __real_main(int argc, char **argv);
extern "C" int __wrap_main(int argc, char **argv) {
  wash::detail::hdf5Opener() = &wash::detail::openSerialHdf5Series;
  return wash::detail::runProgram(argc, argv, &__real_main);
}
