//===- wash.cpp - the wash command ----------------------------------------===//
//
// wash [options] <simulation.cpp> [-- <compiler flags>]
// wash run [options] <simulation.cpp> [-- <program options>]   (RunCommand.cpp)
// wash cache clean
//
//===----------------------------------------------------------------------===//
#include "RunCommand.h"

#include "wash/translator/Pipeline.h"

#include "llvm/ADT/ArrayRef.h"
#include "llvm/Config/llvm-config.h"
#include "llvm/Support/CommandLine.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/InitLLVM.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

using namespace llvm;
using wash::tr::Backend;

static cl::OptionCategory WashCategory("wash options");
static cl::opt<std::string> Source(cl::Positional, cl::desc("<simulation.cpp>"), cl::Required,
                                   cl::cat(WashCategory));
static cl::opt<Backend> TargetBackend("backend", cl::desc("Backend to generate code for"),
                                      cl::init(Backend::Serial), cl::cat(WashCategory));
static cl::opt<std::string> OutputDir("o", cl::desc("Directory for generated code"),
                                      cl::value_desc("dir"), cl::init("."), cl::cat(WashCategory));
static cl::opt<std::string>
    DepFile("depfile",
            cl::desc("Also write a depfile (Makefile syntax) naming every file the translation "
                     "read: the simulation and each header it includes"),
            cl::value_desc("file"), cl::cat(WashCategory));
static cl::opt<bool>
    Force("force",
          cl::desc("Overwrite generated files that were edited since wash wrote them, or "
                   "that wash did not write (never a file the translation reads)"),
          cl::cat(WashCategory));
static cl::opt<bool> NoCompileGate(
    "no-compile-gate",
    cl::desc("Write the generated project without first type-checking it (to debug wash)"),
    cl::cat(WashCategory));
static cl::opt<bool> DumpModel("dump-model",
                               cl::desc("Print the analysed model of the simulation and stop"),
                               cl::cat(WashCategory));
// Checked as it is parsed, so `--dump-after=help` needs no simulation file.
static cl::opt<std::string>
    DumpAfter("dump-after",
              cl::desc("Print the model right after the named pass and stop ('help' lists them)"),
              cl::value_desc("pass"), cl::cat(WashCategory),
              cl::callback([](const std::string &Name) {
                if (Name == "help") {
                  outs() << wash::tr::passNames("\n") << "\n";
                  std::exit(wash::tr::checkedStdout() ? 0 : 1);
                }
                if (!wash::tr::findPass(Name)) {
                  errs() << "wash: error: unknown pass '" << Name
                         << "'; passes are: " << wash::tr::passNames(", ") << "\n";
                  std::exit(1);
                }
              }));

int main(int Argc, const char **Argv) {
  InitLLVM X(Argc, Argv);
  // Everything after `--` goes to the compiler, as with clang tools.
  int Ours = Argc;
  for (int I = 1; I < Argc; ++I)
    if (std::strcmp(Argv[I], "--") == 0) {
      Ours = I;
      break;
    }
  // The --backend values: one per line of backends/backends.def.
  for (const wash::tr::BackendInfo &B : wash::tr::allBackends())
    TargetBackend.getParser().addLiteralOption(B.Name, B.Id, B.Description);
  cl::HideUnrelatedOptions(WashCategory);
  wash::tr::registerSubcommands();
  cl::SetVersionPrinter(
      [](raw_ostream &OS) { OS << "wash " WASH_VERSION " (LLVM " LLVM_VERSION_STRING ")\n"; });
  if (!cl::ParseCommandLineOptions(Ours, Argv,
                                   "wash: translates a wash SPH simulation into a specialised "
                                   "program\n\n  wash [options] <simulation.cpp> [-- <compiler "
                                   "flags>]\n  wash run [options] <simulation.cpp> [-- <program "
                                   "options>]\n  wash cache clean\n"))
    return 1;
  std::string Executable = sys::fs::getMainExecutable(Argv[0], reinterpret_cast<void *>(&main));
  std::vector<std::string> AfterDashes(Argv + std::min(Ours + 1, Argc), Argv + Argc);
  if (std::optional<int> Status = wash::tr::runSubcommand(AfterDashes, Executable))
    return *Status;

  wash::tr::Options Opts;
  Opts.Source = Source;
  Opts.CompilerArgs = std::move(AfterDashes);
  Opts.Target = TargetBackend;
  Opts.OutputDir = OutputDir;
  Opts.DepFile = DepFile;
  Opts.DumpModel = DumpModel;
  Opts.CompileGate = !NoCompileGate;
  Opts.Force = Force;
  if (DumpAfter.getNumOccurrences())
    Opts.DumpAfter = wash::tr::findPass(DumpAfter);
  Opts.ExecutablePath = Executable;
  return wash::tr::runPipeline(Opts);
}
