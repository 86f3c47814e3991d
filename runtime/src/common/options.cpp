#include <wash/detail/options.hpp>

#include <charconv>
#include <cmath>
#include <cstring>

namespace wash::detail {
namespace {

std::uint64_t parseCount(const std::string &option, const std::string &text) {
  std::uint64_t value = 0;
  const char *end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end)
    throw OptionError("option '" + option + "' expects a non-negative integer, got '" + text + "'");
  return value;
}

double parseTime(const std::string &option, const std::string &text, bool positive) {
  double value = 0.0;
  const char *end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value) || value < 0.0 ||
      (positive && value == 0.0))
    throw OptionError("option '" + option + "' expects a " +
                      (positive ? "positive" : "non-negative") + " simulated time, got '" + text +
                      "'");
  return value;
}

double parseSeconds(const std::string &option, const std::string &text) {
  double value = 0.0;
  const char *end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value) || value < 0.0)
    throw OptionError("option '" + option + "' expects a non-negative number of seconds (0: " +
                      "off), got '" + text + "'");
  return value;
}

std::vector<std::string> parseFields(const std::string &text) {
  std::vector<std::string> fields;
  std::size_t from = 0;
  while (true) {
    const std::size_t comma = text.find(',', from);
    std::string name = text.substr(from, comma == std::string::npos ? comma : comma - from);
    if (name.empty())
      throw OptionError("option '--fields' expects field names separated by commas, got '" + text +
                        "'");
    fields.push_back(name);
    if (comma == std::string::npos)
      return fields;
    from = comma + 1;
  }
}

OutputFormat parseFormat(const std::string &text) {
  if (text == "vtk")
    return OutputFormat::Vtk;
  if (text == "csv")
    return OutputFormat::Csv;
  if (text == "hdf5")
    return OutputFormat::Hdf5;
  throw OptionError("option '--format' expects 'vtk', 'csv' or 'hdf5', got '" + text + "'");
}

bool takesValue(const std::string &name) {
  return name == "--steps" || name == "--out" || name == "--output-every" || name == "--format" ||
         name == "--dump" || name == "--end-time" || name == "--output-dt" ||
         name == "--vtk-encoding" || name == "--fields" || name == "--checkpoint-every" ||
         name == "--checkpoint-dt" || name == "--checkpoint-dir" || name == "--keep-checkpoints" ||
         name == "--restart" || name == "--watchdog";
}

void apply(RunOptions &o, const std::string &name, const std::string &value) {
  if (name == "--steps")
    o.steps = parseCount(name, value);
  else if (name == "--out")
    o.outDir = value;
  else if (name == "--output-every")
    o.outputEvery = parseCount(name, value);
  else if (name == "--format")
    o.format = parseFormat(value);
  else if (name == "--dump")
    o.dumpPath = value;
  else if (name == "--end-time")
    o.endTime = parseTime(name, value, /*positive=*/false);
  else if (name == "--output-dt")
    o.outputDt = parseTime(name, value, /*positive=*/true);
  else if (name == "--vtk-encoding") {
    if (value != "binary" && value != "ascii")
      throw OptionError("option '--vtk-encoding' expects 'binary' or 'ascii', got '" + value + "'");
    o.vtkAscii = value == "ascii";
  } else if (name == "--fields")
    o.fields = parseFields(value);
  else if (name == "--checkpoint-every")
    o.checkpointEvery = parseCount(name, value);
  else if (name == "--checkpoint-dt")
    o.checkpointDt = parseTime(name, value, /*positive=*/true);
  else if (name == "--checkpoint-dir")
    o.checkpointDir = value;
  else if (name == "--keep-checkpoints") {
    o.keepCheckpoints = parseCount(name, value);
    if (o.keepCheckpoints == 0)
      throw OptionError("option '--keep-checkpoints' expects at least 1");
  } else if (name == "--restart")
    o.restartPath = value;
  else if (name == "--watchdog")
    o.watchdog = parseSeconds(name, value);
  if (value.empty() &&
      (name == "--out" || name == "--dump" || name == "--checkpoint-dir" || name == "--restart"))
    throw OptionError("option '" + name + "' expects a path");
}

} // namespace

ParsedArgs parseProgramOptions(int argc, char **argv) {
  ParsedArgs parsed;
  if (argc > 0)
    parsed.userArgv.push_back(argv[0]);
  bool passThrough = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (passThrough || arg.rfind("--", 0) != 0 || arg == "-") {
      parsed.userArgv.push_back(argv[i]);
      continue;
    }
    if (arg == "--") {
      passThrough = true;
      continue;
    }
    std::string name = arg, value;
    bool inlineValue = false;
    if (auto eq = arg.find('='); eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
      inlineValue = true;
    }
    if (name == "--quiet" || name == "--help" || name == "--profile") {
      if (inlineValue)
        throw OptionError("option '" + name + "' takes no value");
      (name == "--quiet"  ? parsed.options.quiet
       : name == "--help" ? parsed.options.help
                          : parsed.options.profile) = true;
    } else if (takesValue(name)) {
      if (!inlineValue) {
        if (i + 1 >= argc)
          throw OptionError("option '" + name + "' expects a value");
        value = argv[++i];
      }
      apply(parsed.options, name, value);
    } else {
      throw OptionError("unknown option '" + arg +
                        "' (see --help; put simulation arguments after '--')");
    }
  }
  parsed.userArgv.push_back(nullptr);
  return parsed;
}

std::string usageText(const std::string &program) {
  return "usage: " + program +
         " [wash options] [simulation arguments]\n"
         "\n"
         "wash options (removed before the simulation's main sees argv):\n"
         "  --steps N          run N iterations (overrides set_max_iterations)\n"
         "  --out DIR          output directory (default: out)\n"
         "  --output-every K   write a frame every K steps; 0 = final state only (default 0)\n"
         "  --end-time T       stop after the iteration at whose end the simulated time\n"
         "                     reaches T (overrides wash::set_end_time)\n"
         "  --output-dt T      also write a frame whenever the simulated time crosses a\n"
         "                     multiple of T (frame 0 and the last step too)\n"
         "  --fields A,B,...   frames hold id, pos and these fields only (default: all,\n"
         "                     acc included; --dump always holds every field but acc)\n"
         "  --vtk-encoding binary|ascii  VTK frames' arrays: raw binary, appended (default),\n"
         "                     or text\n"
         "  --format vtk|csv   frame format: .vtp files plus a .pvd series, or .csv (default vtk)\n"
         "  --format hdf5      all frames in one <name>.h5 file, H5Part layout (Step#0, ...)\n"
         "  --dump FILE        write the final state as CSV, one row per particle sorted by id\n"
         "  --checkpoint-every K  write a checkpoint after every K-th iteration\n"
         "  --checkpoint-dt T  write a checkpoint whenever the simulated time crosses a\n"
         "                     multiple of T\n"
         "  --checkpoint-dir DIR  where checkpoints go (default: <out>/checkpoints)\n"
         "  --keep-checkpoints N  keep the newest N complete checkpoints (default 2)\n"
         "  --restart PATH     continue from a checkpoint (or a folder's newest complete\n"
         "                     one); iterations count from the start of the simulation\n"
         "                     (SIGTERM or SIGINT: finish the iteration, checkpoint, exit 75)\n"
         "  --watchdog S       MPI: end the job when a rank stops answering for S\n"
         "                     seconds (default: 10 times the longest wait between two\n"
         "                     collective calls, at least 60); 0 = off\n"
         "  --profile          at the end, a table of where the steps' time went: each\n"
         "                     kernel, the neighbour search, MPI halo exchanges, output\n"
         "  --quiet            no run header, progress line or summary\n"
         "  --help             print this text and exit\n"
         "  --                 pass everything after it to the simulation\n";
}

} // namespace wash::detail
