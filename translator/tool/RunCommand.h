//===- RunCommand.h - the wash run and wash cache subcommands ---*- C++ -*-===//
#pragma once

#include "llvm/ADT/ArrayRef.h"
#include "llvm/ADT/StringRef.h"

#include <optional>
#include <string>

namespace wash::tr {

/// Readies the subcommands' options; before the command line is parsed.
void registerSubcommands();

/// Runs the subcommand the command line chose, with AfterDashes (what
/// followed `--`) for the program; none if it chose none.
std::optional<int> runSubcommand(llvm::ArrayRef<std::string> AfterDashes,
                                 llvm::StringRef ExecutablePath);

} // namespace wash::tr
