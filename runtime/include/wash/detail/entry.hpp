//===- wash/detail/entry.hpp - the entry point every wash program shares -*- C++ -*-===//
#pragma once

#include <wash/detail/options.hpp>

namespace wash::detail {

/// What a runtime's __wrap_main does: parse and strip the wash options (--help
/// prints usage), keep them in programOptions() (run_settings.hpp), run the
/// simulation's main with the rest, and turn every error into a message and
/// an exit status (2 for a bad command line, 1 for anything else).
int runProgram(int argc, char **argv, int (*simulationMain)(int, char **));

} // namespace wash::detail
