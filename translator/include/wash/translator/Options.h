//===- Options.h - what the command line asked for --------------*- C++ -*-===//
#pragma once

#include "wash/translator/Backends.h"

#include <string>
#include <vector>

namespace wash::tr {

struct Options {
  std::string Source;                    ///< The simulation file.
  std::vector<std::string> CompilerArgs; ///< After `--`.
  Backend Target = Backend::Serial;
  std::string OutputDir = ".";
  bool DumpModel = false;
  std::string ExecutablePath; ///< To find an installed wash's API headers.
};

} // namespace wash::tr
