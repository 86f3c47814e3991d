#include <wash/detail/output_folder.hpp>
#include <wash/detail/run_output.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <thread>
#include <vector>

namespace fs = std::filesystem;

namespace wash::detail {
namespace {

constexpr char partialMark[] = ".wash-partial.";

std::string reason(int error) { return error ? std::strerror(error) : "unknown error"; }

/// Who this process is, as the lock file tells a run it refuses.
std::string holderText() {
  char host[256] = "";
  if (::gethostname(host, sizeof host - 1) != 0)
    std::strcpy(host, "an unknown host");
  const std::time_t now = std::time(nullptr);
  char started[64] = "";
  std::tm utc{};
  if (::gmtime_r(&now, &utc))
    std::strftime(started, sizeof started, "%Y-%m-%d %H:%M:%S UTC", &utc);
  return "pid " + std::to_string(::getpid()) + " on host " + host + ", started " + started + " (" +
         program_invocation_name + ")\n";
}

/// The lock file's text, waiting a moment for a run that has just taken the
/// lock to write it.
std::string readHolder(int fd) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    char text[1024];
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    if (n > 0) {
      std::string s(text, std::size_t(n));
      while (!s.empty() && (s.back() == '\n' || s.back() == '\0'))
        s.pop_back();
      return s;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return "its lock file does not say which";
}

bool sameFile(int fd, const std::string &path) {
  struct stat opened{}, named{};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 &&
         opened.st_dev == named.st_dev && opened.st_ino == named.st_ino;
}

} // namespace

FolderLock::FolderLock(const std::string &folder, const std::string &what,
                       const std::string &option)
    : path_((fs::path(folder) / ".wash-lock").string()) {
  // A run that ends removes the file before it releases the lock: a lock
  // taken on a file no longer under its name is taken again, on the new one.
  for (int attempt = 0;; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw RunError(what + " '" + folder + "' is not writable: cannot create '" + path_ +
                     "': " + reason(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      if (error == EWOULDBLOCK) {
        const std::string holder = readHolder(fd_);
        ::close(fd_);
        fd_ = -1;
        throw RunError(what + " '" + folder + "' is in use by another run: " + holder +
                       "; wait for that run to end, or give this one another " + option);
      }
      ::close(fd_); // a file system without locks: nothing to guard with
      fd_ = -1;
      return;
    }
    if (sameFile(fd_, path_))
      break;
    ::close(fd_);
    if (attempt == 100)
      throw RunError("cannot lock " + what + " '" + folder + "': its lock file '" + path_ +
                     "' keeps being replaced");
  }
  // The lock holds without its text (a full disk), so failures here are no error.
  const std::string text = holderText();
  if (::ftruncate(fd_, 0) == 0)
    (void)!::pwrite(fd_, text.data(), text.size(), 0);
}

FolderLock::~FolderLock() {
  if (fd_ < 0)
    return;
  ::unlink(path_.c_str());
  ::close(fd_);
}

void checkWritableFolder(const std::string &folder, const std::string &what) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec || !fs::is_directory(folder))
    throw RunError("cannot create " + what + " '" + folder +
                   "': " + (ec ? ec.message() : "not a directory"));
  const std::string probe = partialPath((fs::path(folder) / ".wash-write-test").string());
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw RunError(what + " '" + folder + "' is not writable: " + reason(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

std::string partialPath(const std::string &path, std::uint64_t owner) {
  return path + partialMark + std::to_string(owner);
}

std::string partialPath(const std::string &path) {
  return partialPath(path, std::uint64_t(::getpid()));
}

namespace {

/// The partial files in `folder` of processes of this host that no longer
/// run, with the name each is the partial file of.
std::vector<std::pair<fs::path, std::string>> stalePartials(const std::string &folder) {
  std::error_code ec;
  std::vector<std::pair<fs::path, std::string>> stale;
  for (const fs::directory_entry &d : fs::directory_iterator(folder, ec)) {
    const std::string name = d.path().filename().string();
    const std::size_t at = name.rfind(partialMark);
    if (at == std::string::npos)
      continue;
    const std::string pid = name.substr(at + sizeof partialMark - 1);
    if (pid.empty() || pid.size() > 9 || pid.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (::kill(pid_t(std::stol(pid)), 0) != 0 && errno == ESRCH)
      stale.emplace_back(d.path(), name.substr(0, at));
  }
  return stale;
}

} // namespace

bool adoptStalePartial(const std::string &path) {
  const fs::path target(path);
  std::error_code ec;
  fs::path newest;
  fs::file_time_type newestTime;
  for (const auto &[file, of] :
       stalePartials(target.parent_path().empty() ? "." : target.parent_path().string())) {
    const fs::file_time_type t = fs::last_write_time(file, ec);
    if (of == target.filename().string() && !ec && (newest.empty() || t > newestTime)) {
      newest = file;
      newestTime = t;
    }
  }
  if (newest.empty())
    return false;
  fs::rename(newest, partialPath(path), ec);
  return !ec;
}

void removeStalePartials(const std::string &folder) {
  std::error_code ec;
  for (const auto &[file, of] : stalePartials(folder))
    fs::remove(file, ec);
}

} // namespace wash::detail
