//===- CompileGate.cpp ----------------------------------------------------===//
#include "wash/translator/Emit/CompileGate.h"

#include "clang/Basic/Diagnostic.h"
#include "clang/Basic/FileManager.h"
#include "clang/Basic/SourceManager.h"
#include "clang/Frontend/FrontendActions.h"
#include "clang/Tooling/Tooling.h"
#include "llvm/ADT/SmallString.h"
#include "llvm/ADT/StringRef.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/VirtualFileSystem.h"

#include <optional>

using namespace clang;

#ifndef WASH_SOURCE_DIR
#define WASH_SOURCE_DIR ""
#endif
// Folders the build found at configure time (":"-separated), baked in like
// the resource directory: mpi.h's, and omp.h's where clang has none.
#ifndef WASH_MPI_INCLUDE_DIRS
#define WASH_MPI_INCLUDE_DIRS ""
#endif
#ifndef WASH_OPENMP_INCLUDE_DIR
#define WASH_OPENMP_INCLUDE_DIR ""
#endif

namespace wash::tr {
namespace {

namespace path = llvm::sys::path;

/// Every backend but serial runs its loops with OpenMP (backends/openmp and
/// backends/mpi link OpenMP::OpenMP_CXX, which adds -fopenmp).
bool usesOpenMP(Backend B) { return B != Backend::Serial; }

/// Whether this build found what the backend's headers include beyond the
/// standard library: omp.h (in clang's resource directory or the C++
/// compiler's) and mpi.h. Without them the gate cannot parse the program and
/// is skipped, rather than rejecting every program.
bool canCheck(Backend B) {
  if (usesOpenMP(B) && std::string(WASH_OPENMP_INCLUDE_DIR).empty() &&
      !llvm::sys::fs::exists(WASH_CLANG_RESOURCE_DIR "/include/omp.h"))
    return false;
  return !backendInfo(B).Distributed || !std::string(WASH_MPI_INCLUDE_DIRS).empty();
}

/// Collects clang's errors instead of printing them.
class ErrorCollector : public DiagnosticConsumer {
public:
  ErrorCollector(const std::string &ProjectDir) : ProjectDir(ProjectDir) {}
  std::vector<CompileError> Errors;

  void HandleDiagnostic(DiagnosticsEngine::Level Level, const Diagnostic &Info) override {
    DiagnosticConsumer::HandleDiagnostic(Level, Info);
    if (Level < DiagnosticsEngine::Error)
      return;
    CompileError E;
    llvm::SmallString<256> Message;
    Info.FormatDiagnostic(Message);
    // Clang's "too many errors emitted" says nothing about the program.
    if (Info.getID() == diag::fatal_too_many_errors)
      return;
    E.Message = std::string(Message);
    if (Info.hasSourceManager() && Info.getLocation().isValid()) {
      const SourceManager &SM = Info.getSourceManager();
      SourceLocation Loc = SM.getFileLoc(Info.getLocation());
      PresumedLoc P = SM.getPresumedLoc(Loc);
      if (P.isValid())
        E.Pos = {P.getFilename(), P.getLine(), P.getColumn()};
      if (OptionalFileEntryRef FE = SM.getFileEntryRefForID(SM.getFileID(Loc))) {
        llvm::StringRef Name = FE->getName();
        if (Name.consume_front(ProjectDir) && Name.consume_front("/")) {
          E.GeneratedFile = Name.str();
          E.GeneratedLine = SM.getSpellingLineNumber(Loc);
        }
      }
    }
    Errors.push_back(std::move(E));
  }

private:
  std::string ProjectDir;
};

std::string absolute(const std::string &Path) {
  llvm::SmallString<256> P(Path);
  llvm::sys::fs::make_absolute(P);
  path::remove_dots(P, /*remove_dot_dot=*/true);
  return std::string(P);
}

void appendSplit(std::vector<std::string> &Out, llvm::StringRef List) {
  llvm::SmallVector<llvm::StringRef, 4> Parts;
  List.split(Parts, ':', -1, /*KeepEmpty=*/false);
  for (llvm::StringRef Part : Parts)
    Out.push_back(Part.str());
}

size_t programIndex(const std::vector<GeneratedFile> &Files, const std::string &Program) {
  for (size_t I = 0; I < Files.size(); ++I)
    if (Files[I].Name == Program)
      return I;
  return 0;
}

/// How far below its kernel's comment an error in the driver may be.
constexpr unsigned KernelSectionLines = 40;

/// The registration of the kernel whose section of the driver holds Line of
/// Text, or an invalid position. The driver opens the section of each kernel
/// with `// <function>: <kind> kernel` (DriverParts' kernelComment), in
/// registration order among the kernels of one function and kind.
SourcePos kernelAt(llvm::StringRef Text, unsigned Line, const std::vector<Kernel> &Kernels) {
  llvm::SmallVector<llvm::StringRef, 0> Lines;
  Text.split(Lines, '\n');
  std::vector<unsigned> Seen(Kernels.size(), 0); // Comments met per kernel.
  std::optional<size_t> Current;
  unsigned CurrentLine = 0;
  for (unsigned L = 1; L <= std::min<size_t>(Line, Lines.size()); ++L) {
    llvm::StringRef Trimmed = Lines[L - 1].trim();
    for (size_t K = 0; K < Kernels.size(); ++K) {
      std::string Comment =
          "// " + Kernels[K].Function + ": " + kernelKindName(Kernels[K].Kind) + " kernel";
      if (!Trimmed.starts_with(Comment))
        continue;
      // The n-th such comment is the n-th kernel of that function and kind.
      unsigned Nth = Seen[K]++;
      for (size_t J = 0; J < Kernels.size(); ++J)
        if (Kernels[J].Function == Kernels[K].Function && Kernels[J].Kind == Kernels[K].Kind &&
            Nth-- == 0) {
          Current = J;
          CurrentLine = L;
          break;
        }
      break;
    }
  }
  if (!Current || Line - CurrentLine > KernelSectionLines)
    return {};
  return Kernels[*Current].Pos;
}

} // namespace

std::vector<std::string> backendIncludeDirs(const std::string &ExecutablePath, Backend Target) {
  std::vector<std::string> Dirs;
  // An installed wash has every header under <prefix>/include.
  llvm::SmallString<256> Installed(path::parent_path(path::parent_path(ExecutablePath)));
  path::append(Installed, "include");
  llvm::SmallString<256> Marker(Installed);
  path::append(Marker, "wash", "backend", "program.hpp");
  if (!ExecutablePath.empty() && llvm::sys::fs::exists(Marker)) {
    Dirs.push_back(std::string(Installed));
  } else {
    std::string Source = WASH_SOURCE_DIR;
    Dirs = {Source + "/runtime/include", Source + "/backends/common/include",
            Source + "/backends/" + backendName(Target) + "/include"};
    // mpi's generated code also runs the OpenMP backend's loops.
    if (usesOpenMP(Target) && Target != Backend::OpenMP)
      Dirs.push_back(Source + "/backends/openmp/include");
  }
  if (backendInfo(Target).Distributed)
    appendSplit(Dirs, WASH_MPI_INCLUDE_DIRS);
  return Dirs;
}

std::vector<CompileError> checkGeneratedCode(const std::vector<GeneratedFile> &Files,
                                             const CompileGateSetup &Setup,
                                             const std::vector<Kernel> &Kernels) {
  if (!canCheck(Setup.Target))
    return {};
  std::string ProjectDir = absolute(Setup.ProjectDir);
  auto Memory = llvm::makeIntrusiveRefCnt<llvm::vfs::InMemoryFileSystem>();
  for (const GeneratedFile &F : Files)
    Memory->addFile(ProjectDir + "/" + F.Name, 0, llvm::MemoryBuffer::getMemBufferCopy(F.Text));
  auto Overlay =
      llvm::makeIntrusiveRefCnt<llvm::vfs::OverlayFileSystem>(llvm::vfs::getRealFileSystem());
  Overlay->pushOverlay(Memory);
  auto FileMgr = llvm::makeIntrusiveRefCnt<FileManager>(FileSystemOptions(), Overlay);

  // As the generated CMakeLists.txt builds it (CXX_EXTENSIONS OFF).
  std::vector<std::string> Args = {"wash-compile-gate", "-fsyntax-only", "-x", "c++", "-std=c++20",
                                   "-resource-dir=" WASH_CLANG_RESOURCE_DIR,
                                   // No "N errors generated." of its own.
                                   "-fno-caret-diagnostics"};
  if (usesOpenMP(Setup.Target)) {
    Args.push_back("-fopenmp");
    if (std::string Dir = WASH_OPENMP_INCLUDE_DIR; !Dir.empty()) {
      // GCC's omp.h, after every other folder so that only omp.h comes from
      // the compiler's own headers, through a wrapper that hides the GCC 11
      // attribute __malloc__(deallocator) clang rejects.
      std::string Wrapper = ProjectDir + "/.wash-compile-gate";
      Memory->addFile(
          Wrapper + "/omp.h", 0,
          llvm::MemoryBuffer::getMemBuffer("#define __malloc__(deallocator) __malloc__\n"
                                           "#include_next <omp.h>\n"
                                           "#undef __malloc__\n"));
      Args.insert(Args.end(), {"-isystem", Wrapper, "-idirafter", Dir});
    }
  }
  Args.insert(Args.end(), {"-I", ProjectDir});
  for (const std::string &Dir : backendIncludeDirs(Setup.ExecutablePath, Setup.Target))
    Args.insert(Args.end(), {"-isystem", Dir});
  Args.insert(Args.end(), Setup.UserArgs.begin(), Setup.UserArgs.end());
  Args.push_back(ProjectDir + "/" + Setup.Program);

  ErrorCollector Collector(ProjectDir);
  tooling::ToolInvocation Invocation(Args, std::make_unique<SyntaxOnlyAction>(), FileMgr.get());
  Invocation.setDiagnosticConsumer(&Collector);
  if (!Invocation.run() && Collector.Errors.empty())
    Collector.Errors.push_back({{}, "", 0, "clang could not run on the generated code", {}});
  for (CompileError &E : Collector.Errors)
    if (E.GeneratedFile == Setup.Program)
      E.Kernel = kernelAt(Files[programIndex(Files, Setup.Program)].Text, E.GeneratedLine, Kernels);
  return std::move(Collector.Errors);
}

} // namespace wash::tr
