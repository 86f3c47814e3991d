//===- BuildCache.h - where `wash run` keeps its builds ---------*- C++ -*-===//
//
// One folder per simulation file, backend (or reference) and compiler under
// $XDG_CACHE_HOME/wash (default ~/.cache/wash). Each holds the generated
// project, its build, and a record of what the build was made from: a
// digest of the configuration (wash, the compiler, the backend) and the
// SHA-256 of every file the translation read. The build is current while
// the record matches; otherwise it is translated and built again in place.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "wash/translator/InputFile.h"

#include "llvm/ADT/ArrayRef.h"
#include "llvm/ADT/StringRef.h"

#include <string>

namespace wash::tr {

/// The cache's folder; "" (and Error set) if neither XDG_CACHE_HOME nor HOME
/// gives one.
std::string cacheRoot(std::string &Error);

/// Removes the cache and everything in it. Returns "" or what went wrong.
std::string cleanCache();

/// The name of the entry for a simulation (its real path) built with
/// Configuration (the backend, the compiler): `<stem>-<Label>-<digest>`.
std::string entryName(llvm::StringRef RealSource, llvm::StringRef Label,
                      llvm::StringRef Configuration);

/// Whether the record in Entry says its build was made from Configuration
/// and from files that all still hold what they held then.
bool buildIsCurrent(llvm::StringRef Entry, llvm::StringRef Configuration);

/// Records that Entry's build was made from Configuration and Inputs.
/// Returns "" or what went wrong.
std::string recordBuild(llvm::StringRef Entry, llvm::StringRef Configuration,
                        llvm::ArrayRef<InputFile> Inputs);

/// Forgets Entry's record, before its build changes: a build stopped half
/// way is never taken for current.
std::string forgetBuild(llvm::StringRef Entry);

/// An exclusive lock on a cache entry, held while it is checked and built:
/// concurrent runs of one simulation wait for each other's build, then find
/// it current.
class EntryLock {
public:
  /// Blocks until Entry (created if need be) is locked; Error set if it
  /// cannot be.
  EntryLock(llvm::StringRef Entry, std::string &Error);
  ~EntryLock();
  EntryLock(const EntryLock &) = delete;
  EntryLock &operator=(const EntryLock &) = delete;
  /// Unlocks early (before the simulation runs for as long as it likes).
  void release();

private:
  int FD = -1;
};

} // namespace wash::tr
