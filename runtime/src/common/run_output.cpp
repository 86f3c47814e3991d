#include <wash/detail/run_output.hpp>
#include <wash/detail/writers.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace wash::detail {
namespace {

template <typename WriteFn> void writeFile(const std::string &path, WriteFn write) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw RunError("cannot open '" + path + "' for writing");
  write(out);
  out.flush();
  if (!out)
    throw RunError("error while writing '" + path + "'");
}

} // namespace

RunOutput::RunOutput(const RunOptions &options, std::string baseName)
    : options_(options), baseName_(std::move(baseName)) {
  std::error_code ec;
  fs::create_directories(options_.outDir, ec);
  if (ec || !fs::is_directory(options_.outDir))
    throw RunError("cannot create output directory '" + options_.outDir +
                   "': " + (ec ? ec.message() : "not a directory"));
  // Fail before the run, not after hours of it.
  std::string probe = (fs::path(options_.outDir) / ".wash-write-test").string();
  {
    std::ofstream out(probe);
    if (!out)
      throw RunError("output directory '" + options_.outDir + "' is not writable");
  }
  fs::remove(probe, ec);
}

bool frameDue(const RunOptions &options, std::uint64_t step, std::uint64_t lastStep) {
  if (step == lastStep)
    return true;
  return options.outputEvery > 0 && step % options.outputEvery == 0;
}

std::string RunOutput::framePath(std::uint64_t step) const {
  char suffix[32];
  std::snprintf(suffix, sizeof suffix, "_%06llu.%s", static_cast<unsigned long long>(step),
                options_.format == OutputFormat::Vtk ? "vtp" : "csv");
  return baseName_ + suffix;
}

void RunOutput::writeFrame(std::uint64_t step, const Frame &frame) {
  std::string file = framePath(step);
  std::string path = (fs::path(options_.outDir) / file).string();
  if (options_.format == OutputFormat::Vtk)
    writeFile(path, [&](std::ostream &out) { writeVtp(frame, out); });
  else
    writeFile(path, [&](std::ostream &out) { writeCsv(frame, out); });
  written_.emplace_back(static_cast<double>(step), file);
}

void RunOutput::finish(const Frame &finalFrame) {
  if (options_.format == OutputFormat::Vtk && !written_.empty()) {
    std::string path = (fs::path(options_.outDir) / (baseName_ + ".pvd")).string();
    writeFile(path, [&](std::ostream &out) { writePvd(written_, out); });
  }
  if (!options_.dumpPath.empty())
    writeCsvFile(finalFrame, options_.dumpPath);
}

void writeCsvFile(const Frame &frame, const std::string &path) {
  writeFile(path, [&](std::ostream &out) { writeCsv(frame, out); });
}

} // namespace wash::detail
