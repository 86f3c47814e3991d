//===- WriteProject.cpp - the generated files, written atomically ---------===//
#include "wash/translator/Emit/WriteProject.h"

#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"

namespace wash::tr {

std::string writeProject(const std::string &Dir, const std::vector<GeneratedFile> &Files) {
  if (std::error_code EC = llvm::sys::fs::create_directories(Dir))
    return "cannot create output directory '" + Dir + "': " + EC.message();
  for (const GeneratedFile &F : Files) {
    llvm::SmallString<256> Path(Dir);
    llvm::sys::path::append(Path, F.Name);
    std::string Temp = (Path + ".tmp").str();
    {
      std::error_code EC;
      llvm::raw_fd_ostream OS(Temp, EC);
      if (EC)
        return "cannot write '" + Temp + "': " + EC.message();
      OS << F.Text;
      OS.close();
      if (OS.has_error()) {
        OS.clear_error();
        llvm::sys::fs::remove(Temp);
        return "error while writing '" + Temp + "'";
      }
    }
    if (std::error_code EC = llvm::sys::fs::rename(Temp, Path))
      return "cannot rename '" + Temp + "' to '" + std::string(Path) + "': " + EC.message();
  }
  return "";
}

} // namespace wash::tr
