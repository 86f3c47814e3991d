//===- ReadableFiles.cpp - what the translation may read ------------------===//
#include "wash/translator/Frontend/ReadableFiles.h"

#include "llvm/Support/FileSystem.h"

#include <system_error>

namespace wash::tr {
namespace {

namespace fs = llvm::sys::fs;

enum class Refusal { NotRegular = 1, TooLarge };

/// The messages clang prints after "cannot open file '...': ".
class RefusalCategory : public std::error_category {
public:
  const char *name() const noexcept override { return "wash input"; }
  std::string message(int Code) const override {
    if (static_cast<Refusal>(Code) == Refusal::TooLarge)
      return "it is larger than " + std::to_string(MaxInputBytes >> 20) +
             " MB; wash reads no larger file";
    return "it is not a regular file (a device, FIFO or socket); wash reads only regular files";
  }
};

std::error_code refusal(Refusal R) {
  static const RefusalCategory Category;
  return {static_cast<int>(R), Category};
}

/// The error for a file the translation must not open; none if it may
/// (a missing file or a directory is left to clang, which reports them).
std::error_code refusalFor(const fs::file_status &Status) {
  if (Status.type() == fs::file_type::directory_file ||
      Status.type() == fs::file_type::regular_file)
    return Status.type() == fs::file_type::regular_file && Status.getSize() > MaxInputBytes
               ? refusal(Refusal::TooLarge)
               : std::error_code();
  return refusal(Refusal::NotRegular);
}

/// The real file system, refusing to open what refusalFor refuses. The
/// check is a stat: opening a FIFO would itself block.
class ReadableFilesOnly : public llvm::vfs::ProxyFileSystem {
public:
  using ProxyFileSystem::ProxyFileSystem;
  llvm::ErrorOr<std::unique_ptr<llvm::vfs::File>>
  openFileForRead(const llvm::Twine &Path) override {
    llvm::SmallString<256> Storage;
    llvm::StringRef Name = Path.toStringRef(Storage);
    fs::file_status Status;
    // Relative names are the underlying FS's: ask it where it is.
    llvm::SmallString<256> Absolute(Name);
    if (!getUnderlyingFS().makeAbsolute(Absolute) && !fs::status(Absolute, Status))
      if (std::error_code EC = refusalFor(Status))
        return EC;
    return ProxyFileSystem::openFileForRead(Path);
  }
};

} // namespace

std::string unreadableReason(llvm::StringRef Path) {
  fs::file_status Status;
  if (std::error_code EC = fs::status(Path, Status))
    return EC.message();
  if (Status.type() == fs::file_type::directory_file)
    return "it is a directory";
  if (std::error_code EC = refusalFor(Status))
    return EC.message();
  return "";
}

llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem>
readableFilesOnly(llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem> FS) {
  return llvm::makeIntrusiveRefCnt<ReadableFilesOnly>(std::move(FS));
}

} // namespace wash::tr
