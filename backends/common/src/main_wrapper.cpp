//===- main_wrapper.cpp - the entry point of generated programs --------===//
//
// Generated programs link with -Wl,--wrap=main, as reference programs do.
//
//===----------------------------------------------------------------------===//
#include <wash/detail/entry.hpp>

extern "C" int __real_main(int argc, char **argv);
extern "C" int __wrap_main(int argc, char **argv) {
  return wash::detail::runProgram(argc, argv, &__real_main);
}
