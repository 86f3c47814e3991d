#include <wash/detail/checkpoint.hpp>
#include <wash/detail/hdf5_series.hpp>
#include <wash/detail/output_folder.hpp>
#include <wash/detail/processes.hpp>
#include <wash/detail/run_output.hpp>
#include <wash/detail/spread_writers.hpp>
#include <wash/detail/writers.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace fs = std::filesystem;

namespace wash::detail {
namespace {

std::string reason(int error) { return error ? std::strerror(error) : "unknown error"; }

/// Whether `path` exists and is not a regular file (a device such as
/// /dev/stdout, a pipe): written in place, as nothing can be renamed onto it.
bool special(const std::string &path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  return !ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status);
}

/// Writes a file whole or not at all: into partialPath(path), renamed onto
/// path once every byte is out. On failure (a full disk, say) the partial file
/// is removed, so no truncated frame is left looking like a frame.
template <typename WriteFn> void writeFile(const std::string &path, WriteFn write) {
  const bool inPlace = special(path);
  const std::string partial = inPlace ? path : partialPath(path);
  std::ofstream out(partial, std::ios::binary);
  if (!out)
    throw RunError("cannot open '" + path + "' for writing: " + reason(errno));
  errno = 0;
  write(out);
  out.flush();
  out.close();
  const int error = errno;
  std::error_code ec;
  if (!out) {
    if (inPlace)
      throw RunError("error while writing '" + path + "': " + reason(error));
    fs::remove(partial, ec);
    throw RunError("error while writing '" + path + "': " + reason(error) +
                   " (the partial file was removed)");
  }
  if (inPlace)
    return;
  fs::rename(partial, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(partial, ignored);
    throw RunError("cannot write '" + path + "': " + ec.message());
  }
}

/// Creates `path` with `bytes` of disk space allocated, then removes it: the
/// run's writes there then have a directory, permission and (at the time)
/// the space. An empty string if they do, else why not.
std::string probe(const std::string &path, std::uint64_t bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    return reason(errno);
  int error = bytes ? ::posix_fallocate(fd, 0, off_t(bytes)) : 0;
  if (error == EOPNOTSUPP || error == ENOSYS || error == EINVAL)
    error = 0; // a file system that cannot tell: the writes will
  if (::close(fd) != 0 && !error)
    error = errno;
  std::error_code ec;
  fs::remove(path, ec);
  return error ? reason(error) : "";
}

std::string gib(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", double(bytes) / double(1ull << 30));
  return text;
}

/// Whether the run's rows are spread over several processes.
const Processes *spread() {
  const Processes *p = processes();
  return p && p->count() > 1 ? p : nullptr;
}

/// The H5Part datasets of `columns`: named like the CSV columns, with z and
/// vz zeros in 2D, as H5Part readers expect three coordinates.
std::vector<Hdf5Dataset> hdf5Datasets(const Columns &columns) {
  std::vector<Hdf5Dataset> sets;
  for (const Column *column : columns) {
    const std::vector<std::string> names = csvHeaders(*column);
    for (int c = 0; c < column->components; ++c)
      sets.push_back({names[std::size_t(c)], column, c});
    if (column->components == 2 && (column->name == "pos" || column->name == "vel"))
      sets.push_back({column->name == "pos" ? "z" : "vz", nullptr, 0});
  }
  return sets;
}

} // namespace

const Processes *&processes() {
  static const Processes *p = nullptr;
  return p;
}

Hdf5Opener &hdf5Opener() {
  static Hdf5Opener opener = nullptr;
  return opener;
}

RunStage &runStage() {
  static RunStage stage;
  return stage;
}

std::string RunStage::describe() const {
  if (!begun)
    return "while setting up the run (main, init kernels and create_particle)";
  const std::string when = step == 0      ? "before the first step"
                           : step > steps ? "after the last step"
                                          : "in step " + std::to_string(step);
  return when + ", with " + std::to_string(particles) + " particles";
}

RunError outOfMemory(const std::string &what, std::uint64_t count, std::uint64_t bytesEach) {
  return RunError("out of memory allocating " + std::to_string(count) + " particles x " +
                  std::to_string(bytesEach) + " bytes (" + gib(count * bytesEach) + " GiB) for " +
                  what);
}

std::string checkOutputName(const std::string &name) {
  // A control character but tab and line breaks has no XML form (the .pvd
  // names every frame file).
  if (std::any_of(name.begin(), name.end(), [](char c) {
        return (unsigned char)c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\0';
      }))
    return "output file name '" + name +
           "' holds a control character other than tab and line breaks, which the .pvd series "
           "(XML) cannot name: change set_simulation_name or set_output_file_name";
  if (name.find('/') == std::string::npos && name.find('\0') == std::string::npos)
    return "";
  return "output file name '" + name +
         "' is not a plain file name: output files stay inside the output directory (--out), so "
         "the names given to set_simulation_name and set_output_file_name cannot contain '/'";
}

RunOutput::RunOutput(const RunOptions &options, std::string baseName)
    : options_(options), baseName_(std::move(baseName)), root_(writesFiles()) {
  if (std::string bad = checkOutputName(baseName_); !bad.empty())
    throw RunError(bad);
  if (!root_)
    return;
  std::error_code ec;
  fs::create_directories(options_.outDir, ec);
  if (ec || !fs::is_directory(options_.outDir))
    throw RunError("cannot create output directory '" + options_.outDir +
                   "': " + (ec ? ec.message() : "not a directory"));
  // Fail before the run, not after hours of it: every path the run will
  // write (reserve() checks the space once the frame's size is known).
  if (probe(probePath(), 0) != "")
    throw RunError("output directory '" + options_.outDir + "' is not writable");
  // One run at a time per folder (a second is refused here, naming the first);
  // what a killed run was writing is then nobody's.
  locks_.push_back(std::make_unique<FolderLock>(options_.outDir, "output directory", "--out"));
  // A restart continues the HDF5 series a killed run left in its partial file
  // (this process, rank 0 under MPI, names the shared file): that one is kept.
  const std::string h5 = (fs::path(options_.outDir) / (baseName_ + ".h5")).string();
  if (!options_.restartPath.empty() && options_.format == OutputFormat::Hdf5 && !fs::exists(h5))
    adoptStalePartial(h5);
  removeStalePartials(options_.outDir);
  // Checkpoints asked for, or a folder named for them: it is created and
  // checked now, not at the first checkpoint after an interval's work.
  const std::string checkpoints = checkpointDirectory(options_);
  if (options_.checkpointEvery || options_.checkpointDt || !options_.checkpointDir.empty()) {
    checkWritableFolder(checkpoints, "checkpoint directory");
    if (!fs::equivalent(checkpoints, options_.outDir, ec))
      locks_.push_back(
          std::make_unique<FolderLock>(checkpoints, "checkpoint directory", "--checkpoint-dir"));
  }
  if (!options_.dumpPath.empty()) {
    if (fs::is_directory(options_.dumpPath, ec))
      throw RunError("cannot write the dump to '" + options_.dumpPath + "': it is a directory");
    if (special(options_.dumpPath)) {
      if (::access(options_.dumpPath.c_str(), W_OK) != 0)
        throw RunError("cannot write the dump to '" + options_.dumpPath + "': " + reason(errno));
    } else if (std::string bad = probe(partialPath(options_.dumpPath), 0); !bad.empty())
      throw RunError("cannot write the dump to '" + options_.dumpPath + "': " + bad);
  }
}

RunOutput::~RunOutput() = default;

std::string RunOutput::probePath() const {
  return partialPath((fs::path(options_.outDir) / ".wash-write-test").string());
}

std::uint64_t frameBytesEstimate(const Frame &frame) {
  return frameBytesEstimate(frame, frame.size());
}

std::uint64_t frameBytesEstimate(const Frame &frame, std::uint64_t rows) {
  // A value takes about 16 characters in either format (17 significant
  // digits, fewer for round numbers); ids, VTK connectivity and offsets fewer.
  std::uint64_t perRow = 0;
  for (const Column &column : frame.columns)
    perRow += std::uint64_t(column.components);
  return 16 * perRow * rows + 24 * rows + 4096;
}

void RunOutput::reserve(std::uint64_t bytes) {
  if (!root_)
    return;
  if (std::string bad = probe(probePath(), bytes); !bad.empty())
    throw RunError("cannot write frames to '" + options_.outDir + "': reserving " +
                   std::to_string(bytes) + " bytes (" + gib(bytes) +
                   " GiB, about one frame) failed: " + bad);
  if (options_.dumpPath.empty() || special(options_.dumpPath))
    return;
  if (std::string bad = probe(partialPath(options_.dumpPath), bytes); !bad.empty())
    throw RunError("cannot write the dump to '" + options_.dumpPath + "': reserving " +
                   std::to_string(bytes) + " bytes (" + gib(bytes) +
                   " GiB, about one frame) failed: " + bad);
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

void RunOutput::checkFields(const Frame &frame) const {
  std::vector<std::string> unknown;
  frameColumns(frame, options_.fields, &unknown);
  if (unknown.empty())
    return;
  std::string names;
  for (const Column &c : frame.columns)
    names += ", " + c.name;
  throw RunError("--fields names '" + unknown.front() +
                 "', which is no field of this simulation (its fields: id" + names + ")");
}

void RunOutput::writeFrame(std::uint64_t step, const Frame &frame, std::optional<double> time,
                           bool seriesByTime) {
  std::string file = framePath(step);
  std::string path = (fs::path(options_.outDir) / file).string();
  checkFields(frame);
  const Columns columns = frameColumns(frame, options_.fields);
  if (options_.format == OutputFormat::Hdf5) {
    if (!hdf5_)
      openHdf5(/*restart=*/false);
    hdf5_->write(step, time.value_or(0.0), frame, hdf5Datasets(columns));
    written_.push_back({step, time.value_or(0.0), baseName_ + ".h5"});
    return;
  }
  const VtpOptions vtp{.ascii = options_.vtkAscii, .time = time, .typeNames = frame.typeNames};
  if (const Processes *p = spread()) {
    auto write = [&](std::ostream *out) {
      if (options_.format == OutputFormat::Vtk)
        writeVtpSpread(*p, frame, columns, vtp, out);
      else
        writeCsvSpread(*p, frame, columns, out);
    };
    if (root_)
      writeFile(path, [&](std::ostream &out) { write(&out); });
    else
      write(nullptr);
  } else if (options_.format == OutputFormat::Vtk)
    writeFile(path, [&](std::ostream &out) { writeVtp(frame, columns, vtp, out); });
  else
    writeFile(path, [&](std::ostream &out) { writeCsv(frame, columns, out); });
  written_.push_back({step, time.value_or(0.0), file});
  seriesByTime_ |= time && seriesByTime;
  // After every frame, so that a run killed outright leaves a series of the
  // frames it completed.
  if (root_ && options_.format == OutputFormat::Vtk)
    writeSeries();
}

void RunOutput::writeSeries() const {
  std::string path = (fs::path(options_.outDir) / (baseName_ + ".pvd")).string();
  std::vector<std::pair<double, std::string>> series;
  for (const Written &w : written_)
    series.emplace_back(seriesByTime_ ? w.time : double(w.step), w.file);
  writeFile(path, [&](std::ostream &out) { writePvd(series, out); });
}

void RunOutput::openHdf5(bool restart) {
  if (!hdf5Opener())
    throw RunError("--format hdf5: this program has no HDF5 library linked");
  const std::string h5 = (fs::path(options_.outDir) / (baseName_ + ".h5")).string();
  std::vector<Hdf5Step> keep;
  if (restart)
    for (const Written &w : written_)
      keep.push_back({w.step, w.time});
  // One file, written by every process: named by rank 0's process id.
  const Processes *p = spread();
  const std::string partial =
      partialPath(h5, p ? p->allgather(std::uint64_t(::getpid()))[0] : ::getpid());
  if (!keep.empty() && root_ && !options_.quiet && !fs::exists(h5)) {
    if (fs::exists(partial))
      std::printf("wash: continuing the partial file of %s that a killed run left\n", h5.c_str());
    else
      std::printf("wash: no %s to continue: the restarted series starts at Step#0, with the "
                  "frames after the checkpoint\n",
                  h5.c_str());
  }
  hdf5_ = hdf5Opener()(h5, partial, keep);
}

void RunOutput::continueSeries(std::vector<Written> written, bool seriesByTime) {
  // The frames of this format only (a checkpoint of a run with another
  // --format names other files).
  const std::string suffix = options_.format == OutputFormat::Hdf5  ? ".h5"
                             : options_.format == OutputFormat::Vtk ? ".vtp"
                                                                    : ".csv";
  written_.clear();
  for (Written &w : written)
    if (w.file.size() >= suffix.size() &&
        w.file.compare(w.file.size() - suffix.size(), suffix.size(), suffix) == 0)
      written_.push_back(std::move(w));
  seriesByTime_ = seriesByTime;
  if (options_.format == OutputFormat::Hdf5)
    openHdf5(/*restart=*/true);
  else if (root_ && options_.format == OutputFormat::Vtk)
    writeSeries(); // the frames past the checkpoint are no longer in it
}

void RunOutput::closeSeries() {
  if (!hdf5_)
    return;
  hdf5_->close();
  hdf5_.reset();
}

void RunOutput::finish(const Frame &finalFrame) {
  closeSeries();
  if (root_ && options_.format == OutputFormat::Vtk && !written_.empty())
    writeSeries();
  if (options_.dumpPath.empty())
    return;
  const Processes *p = spread();
  if (!p)
    return writeCsvFile(finalFrame, options_.dumpPath);
  const Columns columns = dumpColumns(finalFrame);
  if (root_)
    writeFile(options_.dumpPath,
              [&](std::ostream &out) { writeCsvSpread(*p, finalFrame, columns, &out); });
  else
    writeCsvSpread(*p, finalFrame, columns, nullptr);
}

void writeCsvFile(const Frame &frame, const std::string &path) {
  writeFile(path, [&](std::ostream &out) { writeCsv(frame, out); });
}

} // namespace wash::detail
