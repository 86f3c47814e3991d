//===- wash/detail/output_folder.hpp - the folders a run writes into -*- C++ -*-===//
//
// One run at a time per folder: a run holds `<folder>/.wash-lock` locked
// (flock) while it writes there, and a second run into the same folder is
// refused at start, told which run holds it (the file says: pid, host, start
// time, program). The kernel releases the lock when the process ends, however
// it ends, so the file a killed run leaves refuses nobody. And every file is
// written under a temporary name no other process uses (partialPath).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <string>

namespace wash::detail {

/// Holds the lock of a folder for this process, from construction to destruction.
class FolderLock {
public:
  /// Locks `folder` (which exists), or throws RunError naming the run that
  /// holds it. `what` names the folder and `option` the option that chose it,
  /// in messages: "output directory", "--out".
  FolderLock(const std::string &folder, const std::string &what, const std::string &option);
  FolderLock(const FolderLock &) = delete;
  FolderLock &operator=(const FolderLock &) = delete;
  /// Removes the file, then releases the lock.
  ~FolderLock();

private:
  std::string path_;
  int fd_ = -1;
};

/// Creates `folder` if need be and checks that a file can be created in it
/// (throws RunError saying why not, naming the folder as `what`).
void checkWritableFolder(const std::string &folder, const std::string &what);

/// Where `path` is written before it is renamed into place: beside it, so on
/// the same file system, and never a name a frame, dump or checkpoint file
/// has: `<path>.wash-partial.<pid>`. `owner` is the writing process's id; all
/// processes writing one file together (parallel HDF5) name rank 0's.
std::string partialPath(const std::string &path, std::uint64_t owner);
std::string partialPath(const std::string &path);

/// Takes over the partial file of `path` that a process of this host left
/// when it was killed (a restart continues an HDF5 series in it): renames the
/// newest `<path>.wash-partial.<pid>` of a dead process to partialPath(path).
/// Returns whether there was one.
bool adoptStalePartial(const std::string &path);

/// Removes the partial files in `folder` of processes of this host that no
/// longer run (killed while writing); files of live processes are left.
void removeStalePartials(const std::string &folder);

} // namespace wash::detail
