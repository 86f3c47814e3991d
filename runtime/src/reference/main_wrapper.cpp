//===- main_wrapper.cpp - the entry point of reference programs ---------===//
//
// The wash targets link with -Wl,--wrap=main, so the program starts here: the
// wash options are stripped, then the simulation's own main runs with the rest.
// Kept apart from the runtime so that unit tests can link the runtime alone.
//
//===----------------------------------------------------------------------===//
#include "state.hpp"

#include <wash/detail/options.hpp>

#include <cstdio>

extern "C" int __real_main(int argc, char **argv);
extern "C" int __wrap_main(int argc, char **argv) {
  std::string program = argc > 0 ? argv[0] : "wash";
  try {
    auto parsed = wash::detail::parseProgramOptions(argc, argv);
    if (parsed.options.help) {
      std::fputs(wash::detail::usageText(program).c_str(), stdout);
      return 0;
    }
    wash::detail::state().options = parsed.options;
    return __real_main(int(parsed.userArgv.size()) - 1, parsed.userArgv.data());
  } catch (const wash::detail::OptionError &e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 2;
  } catch (const wash::detail::UsageError &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::exception &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 1;
  }
}
