//===- Subprocess.cpp - the programs `wash run` starts --------------------===//
#include "wash/translator/Run/Subprocess.h"

#include "llvm/ADT/SmallString.h"
#include "llvm/ADT/SmallVector.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Program.h"
#include "llvm/Support/raw_ostream.h"

#include <cerrno>
#include <cstring>
#include <optional>
#include <unistd.h>

namespace wash::tr {

std::string findProgram(llvm::StringRef Name) {
  if (Name.contains('/'))
    return llvm::sys::fs::can_execute(Name) ? Name.str() : "";
  llvm::ErrorOr<std::string> Path = llvm::sys::findProgramByName(Name);
  return Path ? *Path : "";
}

std::string runLogged(llvm::StringRef Program, llvm::ArrayRef<std::string> Args,
                      llvm::StringRef LogFile) {
  llvm::SmallVector<llvm::StringRef, 16> Argv(Args.begin(), Args.end());
  std::optional<llvm::StringRef> Redirects[] = {llvm::StringRef(""), LogFile, LogFile};
  std::string Message;
  int Status = llvm::sys::ExecuteAndWait(Program, Argv, /*Env=*/std::nullopt, Redirects,
                                         /*SecondsToWait=*/0, /*MemoryLimit=*/0, &Message);
  if (Status == 0)
    return "";
  if (Status < 0)
    return Message.empty() ? "it could not be run" : Message;
  return "it exited with status " + std::to_string(Status);
}

std::string firstOutputLine(llvm::StringRef Program, llvm::ArrayRef<std::string> Args) {
  llvm::SmallString<128> Scratch;
  if (llvm::sys::fs::createTemporaryFile("wash-run", "txt", Scratch))
    return "";
  std::string Line;
  if (runLogged(Program, Args, Scratch).empty())
    if (auto Buffer = llvm::MemoryBuffer::getFile(Scratch))
      Line = (*Buffer)->getBuffer().split('\n').first.str();
  llvm::sys::fs::remove(Scratch);
  return Line;
}

int replaceProcess(const std::string &Program, const std::vector<std::string> &Args) {
  std::vector<char *> Argv;
  for (const std::string &Arg : Args)
    Argv.push_back(const_cast<char *>(Arg.c_str()));
  Argv.push_back(nullptr);
  llvm::outs().flush();
  llvm::errs().flush();
  ::execv(Program.c_str(), Argv.data());
  llvm::errs() << "wash: error: cannot run '" << Program << "': " << std::strerror(errno) << "\n";
  return 127;
}

} // namespace wash::tr
