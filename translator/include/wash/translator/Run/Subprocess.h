//===- Subprocess.h - the programs `wash run` starts ------------*- C++ -*-===//
#pragma once

#include "llvm/ADT/ArrayRef.h"
#include "llvm/ADT/StringRef.h"

#include <string>
#include <vector>

namespace wash::tr {

/// Name's path if it names a program (a path, or a name on PATH); "" if not.
std::string findProgram(llvm::StringRef Name);

/// Runs Program with Args (Args[0] is its name), its standard output and
/// error to LogFile. Returns "" if it exits with 0, else what happened.
std::string runLogged(llvm::StringRef Program, llvm::ArrayRef<std::string> Args,
                      llvm::StringRef LogFile);

/// The first line Program prints when run with Args; "" if none.
std::string firstOutputLine(llvm::StringRef Program, llvm::ArrayRef<std::string> Args);

/// Replaces this process by Program with Args, so that the exit status,
/// signals included, is the program's. Returns only if it cannot: 127, after
/// saying why.
int replaceProcess(const std::string &Program, const std::vector<std::string> &Args);

} // namespace wash::tr
