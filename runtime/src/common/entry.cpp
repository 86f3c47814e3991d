#include <wash/detail/checkpoint.hpp>
#include <wash/detail/entry.hpp>
#include <wash/detail/profile.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/detail/run_settings.hpp>

#include <cstdio>
#include <cstdlib>
#include <cxxabi.h>
#include <new>
#include <string>
#include <typeinfo>

namespace wash::detail {
namespace {

/// The demangled type of the exception being handled ("int"), or "unknown".
std::string currentExceptionType() {
  const std::type_info *type = abi::__cxa_current_exception_type();
  if (!type)
    return "unknown";
  int status = 0;
  char *name = abi::__cxa_demangle(type->name(), nullptr, nullptr, &status);
  std::string text = status == 0 && name ? name : type->name();
  std::free(name);
  return text;
}

} // namespace

int runProgram(int argc, char **argv, int (*simulationMain)(int, char **)) {
  std::string program = argc > 0 ? argv[0] : "wash";
  try {
    ParsedArgs parsed = parseProgramOptions(argc, argv);
    if (parsed.options.help) {
      std::fputs(usageText(program).c_str(), stdout);
      return 0;
    }
    programOptions() = parsed.options;
    profiling = parsed.options.profile;
    return simulationMain(int(parsed.userArgv.size()) - 1, parsed.userArgv.data());
  } catch (const Interrupted &e) {
    std::fflush(stdout);
    if (*e.what())
      std::fprintf(stderr, "%s: %s\n", program.c_str(), e.what());
    return interruptedExitStatus;
  } catch (const OptionError &e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 2;
  } catch (const UsageError &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::bad_alloc &) {
    // An allocation no wash error names (most do: outOfMemory): say when.
    std::fflush(stdout);
    std::fprintf(stderr, "%s: error: out of memory (std::bad_alloc) %s\n", program.c_str(),
                 runStage().describe().c_str());
    return 1;
  } catch (const std::exception &e) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
    return 1;
  } catch (...) {
    // `throw 42;` in a kernel: no message to print, but the type and when.
    std::fflush(stdout);
    std::fprintf(stderr, "%s: error: an exception of type '%s' thrown %s\n", program.c_str(),
                 currentExceptionType().c_str(), runStage().describe().c_str());
    return 1;
  }
}

} // namespace wash::detail
