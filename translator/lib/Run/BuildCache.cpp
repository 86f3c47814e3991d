//===- BuildCache.cpp - where `wash run` keeps its builds -----------------===//
#include "wash/translator/Run/BuildCache.h"
#include "wash/translator/Emit/ProjectManifest.h"

#include "llvm/ADT/SmallString.h"
#include "llvm/ADT/SmallVector.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/Process.h"
#include "llvm/Support/raw_ostream.h"

#include <unistd.h>

namespace wash::tr {
namespace {

namespace fs = llvm::sys::fs;
namespace path = llvm::sys::path;

constexpr llvm::StringLiteral RecordHeader = "# wash run: this build was made from";
constexpr llvm::StringLiteral RecordName = "record";

std::string join(llvm::StringRef Dir, llvm::StringRef Name) {
  llvm::SmallString<256> Path(Dir);
  path::append(Path, Name);
  return std::string(Path);
}

/// The SHA-256 of the file at Path now; "" if it cannot be read.
std::string fileHash(const std::string &Path) {
  auto Buffer = llvm::MemoryBuffer::getFile(Path, /*IsText=*/false,
                                            /*RequiresNullTerminator=*/false);
  return Buffer ? contentHash((*Buffer)->getBuffer()) : "";
}

} // namespace

std::string cacheRoot(std::string &Error) {
  // XDG: a relative XDG_CACHE_HOME is ignored.
  llvm::SmallString<256> Root;
  std::optional<std::string> Xdg = llvm::sys::Process::GetEnv("XDG_CACHE_HOME");
  if (Xdg && path::is_absolute(*Xdg)) {
    Root = *Xdg;
  } else if (path::home_directory(Root)) {
    path::append(Root, ".cache");
  } else {
    Error = "no cache folder: set XDG_CACHE_HOME or HOME";
    return "";
  }
  path::append(Root, "wash");
  return std::string(Root);
}

std::string cleanCache() {
  std::string Error;
  std::string Root = cacheRoot(Error);
  if (Root.empty())
    return Error;
  if (std::error_code EC = fs::remove_directories(Root, /*IgnoreErrors=*/false))
    return "cannot remove '" + Root + "': " + EC.message();
  return "";
}

std::string entryName(llvm::StringRef RealSource, llvm::StringRef Label,
                      llvm::StringRef Configuration) {
  std::string Name = (path::stem(RealSource) + "-" + Label).str();
  for (char &C : Name)
    if (!llvm::isAlnum(C) && C != '_' && C != '-' && C != '.' && C != '+')
      C = '_';
  std::string Key = contentHash((RealSource + "\n" + Configuration).str());
  return Name + "-" + Key.substr(0, 16);
}

bool buildIsCurrent(llvm::StringRef Entry, llvm::StringRef Configuration) {
  auto Buffer = llvm::MemoryBuffer::getFile(join(Entry, RecordName));
  if (!Buffer)
    return false;
  llvm::SmallVector<llvm::StringRef, 64> Lines;
  (*Buffer)->getBuffer().split(Lines, '\n', -1, /*KeepEmpty=*/false);
  if (Lines.size() < 3 || Lines[0] != RecordHeader ||
      Lines[1] != "config " + contentHash(Configuration))
    return false;
  for (llvm::StringRef Line : llvm::ArrayRef(Lines).drop_front(2)) {
    auto [Hash, Path] = Line.split("  ");
    if (Hash.size() != 64 || Path.empty() || fileHash(Path.str()) != Hash)
      return false;
  }
  return true;
}

std::string recordBuild(llvm::StringRef Entry, llvm::StringRef Configuration,
                        llvm::ArrayRef<InputFile> Inputs) {
  std::string Text = RecordHeader.str() + "\nconfig " + contentHash(Configuration) + "\n";
  for (const InputFile &In : Inputs) {
    // Not recordable: the build is made again next time.
    if (In.Hash.empty() || In.Path.find_first_of("\n\r") != std::string::npos)
      return forgetBuild(Entry);
    Text += In.Hash + "  " + In.Path + "\n";
  }
  std::string Record = join(Entry, RecordName);
  std::string Temporary = Record + "." + std::to_string(::getpid());
  {
    std::error_code EC;
    llvm::raw_fd_ostream OS(Temporary, EC);
    if (EC)
      return "cannot write '" + Temporary + "': " + EC.message();
    OS << Text;
    OS.close();
    if (OS.has_error()) {
      std::string Message = OS.error().message();
      OS.clear_error();
      return "cannot write '" + Temporary + "': " + Message;
    }
  }
  if (std::error_code EC = fs::rename(Temporary, Record))
    return "cannot write '" + Record + "': " + EC.message();
  return "";
}

std::string forgetBuild(llvm::StringRef Entry) {
  std::string Record = join(Entry, RecordName);
  if (std::error_code EC = fs::remove(Record))
    return "cannot remove '" + Record + "': " + EC.message();
  return "";
}

EntryLock::EntryLock(llvm::StringRef Entry, std::string &Error) {
  if (std::error_code EC = fs::create_directories(Entry)) {
    Error = "cannot create '" + Entry.str() + "': " + EC.message();
    return;
  }
  std::string Path = join(Entry, "lock");
  if (std::error_code EC = fs::openFileForReadWrite(Path, FD, fs::CD_OpenAlways, fs::OF_None)) {
    Error = "cannot open '" + Path + "': " + EC.message();
    FD = -1;
    return;
  }
  if (std::error_code EC = fs::lockFile(FD)) {
    Error = "cannot lock '" + Path + "': " + EC.message();
    release();
  }
}

EntryLock::~EntryLock() { release(); }

void EntryLock::release() {
  if (FD < 0)
    return;
  fs::unlockFile(FD);
  ::close(FD);
  FD = -1;
}

} // namespace wash::tr
