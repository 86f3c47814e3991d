//===- ReadableFiles.h - what the translation may read ----------*- C++ -*-===//
//
// The translation reads only regular files of bounded size: a FIFO, a
// terminal or /dev/stdin would block it for ever, /dev/zero would read
// without end, a huge file would exhaust memory.
//
//===----------------------------------------------------------------------===//
#pragma once

#include "llvm/ADT/IntrusiveRefCntPtr.h"
#include "llvm/ADT/StringRef.h"
#include "llvm/Support/VirtualFileSystem.h"

#include <cstdint>
#include <string>

namespace wash::tr {

/// The largest file (the simulation or anything it includes) wash reads.
constexpr uint64_t MaxInputBytes = uint64_t(64) << 20;

/// Why Path cannot be read ("" if it can): not found, a directory, not a
/// regular file, or larger than MaxInputBytes. Symbolic links are followed.
std::string unreadableReason(llvm::StringRef Path);

/// FS, except that opening a file unreadableReason refuses fails (before the
/// file is opened) with an error whose message says why; clang reports it at
/// the #include as "cannot open file '...': <why>".
llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem>
readableFilesOnly(llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem> FS);

} // namespace wash::tr
