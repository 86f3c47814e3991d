//===- RunCommand.cpp - the wash run and wash cache subcommands -----------===//
//
// wash run [--backend=B] [--np N] [--reference] [-I dir] <simulation.cpp>
//          [-- <program options>]
// wash cache clean
//
//===----------------------------------------------------------------------===//
#include "RunCommand.h"

#include "wash/translator/Run/BuildCache.h"
#include "wash/translator/Run/RunSimulation.h"

#include "llvm/Support/CommandLine.h"
#include "llvm/Support/raw_ostream.h"

using namespace llvm;
using wash::tr::Backend;

static cl::SubCommand RunCommand("run", "Translate and build a simulation (cached), and run it");
static cl::SubCommand CacheCommand("cache", "Manage the cache of wash run's builds");

static cl::OptionCategory RunCategory("wash run options");
static cl::opt<std::string> RunSource(cl::Positional, cl::desc("<simulation.cpp>"), cl::Required,
                                      cl::sub(RunCommand), cl::cat(RunCategory));
static cl::opt<Backend> RunBackend("backend",
                                   cl::desc("Backend to translate for (default: serial; mpi "
                                            "with --np)"),
                                   cl::init(Backend::Serial), cl::sub(RunCommand),
                                   cl::cat(RunCategory));
static cl::opt<unsigned> Ranks("np",
                               cl::desc("Run N MPI ranks with mpirun (a distributed backend)"),
                               cl::value_desc("N"), cl::sub(RunCommand), cl::cat(RunCategory));
static cl::list<std::string> IncludeDirs("I",
                                         cl::desc("Include the simulation's headers from dir too"),
                                         cl::value_desc("dir"), cl::Prefix, cl::sub(RunCommand),
                                         cl::cat(RunCategory));
static cl::opt<bool> Reference("reference",
                               cl::desc("Run the untranslated program, built against the "
                                        "reference runtime"),
                               cl::sub(RunCommand), cl::cat(RunCategory));

static cl::OptionCategory CacheCategory("wash cache options");
static cl::opt<std::string> CacheAction(cl::Positional, cl::desc("clean"), cl::Required,
                                        cl::sub(CacheCommand), cl::cat(CacheCategory));

namespace wash::tr {

void registerSubcommands() {
  for (const BackendInfo &B : allBackends())
    RunBackend.getParser().addLiteralOption(B.Name, B.Id, B.Description);
  cl::HideUnrelatedOptions({&RunCategory}, RunCommand);
  cl::HideUnrelatedOptions({&CacheCategory}, CacheCommand);
}

/// The request the run options make; none, after a message, if they
/// contradict each other.
static std::optional<RunRequest> runRequest(ArrayRef<std::string> AfterDashes,
                                            StringRef ExecutablePath) {
  RunRequest R;
  R.Source = RunSource;
  R.IncludeDirs.assign(IncludeDirs.begin(), IncludeDirs.end());
  R.ProgramArgs.assign(AfterDashes.begin(), AfterDashes.end());
  R.ExecutablePath = ExecutablePath.str();
  bool BackendGiven = RunBackend.getNumOccurrences() > 0;
  if (Ranks.getNumOccurrences() && Ranks == 0) {
    errs() << "wash run: error: --np needs at least 1 rank\n";
    return std::nullopt;
  }
  if (Reference) {
    if (BackendGiven || Ranks.getNumOccurrences()) {
      errs() << "wash run: error: --reference runs the untranslated program, in one process: "
                "it takes no --backend or --np\n";
      return std::nullopt;
    }
    return R;
  }
  Backend Target = RunBackend;
  if (Ranks.getNumOccurrences() && !BackendGiven)
    for (const BackendInfo &B : allBackends())
      if (B.Distributed) {
        Target = B.Id;
        break;
      }
  R.Target = Target;
  if (backendInfo(Target).Distributed) {
    R.Ranks = Ranks.getNumOccurrences() ? Ranks : 1;
  } else if (Ranks.getNumOccurrences()) {
    errs() << "wash run: error: --np runs MPI ranks, which the " << backendName(Target)
           << " backend does not use: give --backend=mpi, or no --np\n";
    return std::nullopt;
  }
  return R;
}

std::optional<int> runSubcommand(ArrayRef<std::string> AfterDashes, StringRef ExecutablePath) {
  if (RunCommand) {
    std::optional<RunRequest> R = runRequest(AfterDashes, ExecutablePath);
    return R ? runSimulation(*R) : 1;
  }
  if (!CacheCommand)
    return std::nullopt;
  if (CacheAction != "clean") {
    errs() << "wash cache: error: unknown action '" << CacheAction << "'; the one action is "
           << "'clean'\n";
    return 1;
  }
  if (!AfterDashes.empty()) {
    errs() << "wash cache: error: 'clean' takes no arguments\n";
    return 1;
  }
  std::string Error = cleanCache();
  if (!Error.empty()) {
    errs() << "wash cache: error: " << Error << "\n";
    return 1;
  }
  return 0;
}

} // namespace wash::tr
