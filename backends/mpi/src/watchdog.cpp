#include <wash/mpi/watchdog.hpp>

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <list>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace wash::mpi {
namespace {

using Clock = std::chrono::steady_clock;

double now() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

// Written by the main thread only, read by the watchdog's.
std::atomic<double> lastProgress{0.0};
std::atomic<double> longestGap{0.0};

class Watchdog {
public:
  Watchdog(std::optional<double> seconds, std::string program)
      : fixed_(seconds), program_(std::move(program)) {
    MPI_Comm_dup(MPI_COMM_WORLD, &comm_);
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &ranks_);
    lastProgress.store(now(), std::memory_order_relaxed);
    thread_ = std::thread([this] { watch(); });
  }

  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
    for (Pending &p : sent_)
      if (p.request != MPI_REQUEST_NULL)
        MPI_Request_free(&p.request);
    MPI_Comm_free(&comm_);
  }

private:
  static constexpr int pingTag = 1, answerTag = 2;
  struct Pending {
    std::uint64_t round;
    MPI_Request request = MPI_REQUEST_NULL;
  };

  double seconds() const {
    if (fixed_)
      return *fixed_;
    return std::max(defaultWatchdogSeconds, 10.0 * longestGap.load(std::memory_order_relaxed));
  }

  void watch() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stopping_; })) {
      serve();
      check();
    }
  }

  /// Answers other ranks' questions; notes the answers to this rank's.
  void serve() {
    int flag = 0;
    MPI_Status status;
    while (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, comm_, &flag, &status) == MPI_SUCCESS && flag) {
      std::uint64_t round = 0;
      MPI_Recv(&round, 1, MPI_UINT64_T, status.MPI_SOURCE, status.MPI_TAG, comm_,
               MPI_STATUS_IGNORE);
      if (status.MPI_TAG == pingTag)
        send(status.MPI_SOURCE, answerTag, round);
      else if (asking_ && round == round_)
        answered_[std::size_t(status.MPI_SOURCE)] = true;
    }
    sent_.remove_if([](Pending &p) {
      int done = 0;
      MPI_Test(&p.request, &done, MPI_STATUS_IGNORE);
      return done != 0;
    });
  }

  /// Never blocks: a stopped rank must not stop this thread too.
  void send(int to, int tag, std::uint64_t round) {
    sent_.push_back({round});
    MPI_Isend(&sent_.back().round, 1, MPI_UINT64_T, to, tag, comm_, &sent_.back().request);
  }

  void check() {
    const double limit = seconds(), t = now();
    if (!asking_) {
      const double quietSince = std::max(lastProgress.load(std::memory_order_relaxed), lastAsked_);
      if (t - quietSince < limit)
        return;
      asking_ = true, askedAt_ = t, ++round_;
      answered_.assign(std::size_t(ranks_), false);
      answered_[std::size_t(rank_)] = true;
      for (int r = 0; r < ranks_; ++r)
        if (r != rank_)
          send(r, pingTag, round_);
      return;
    }
    if (std::all_of(answered_.begin(), answered_.end(), [](bool a) { return a; })) {
      asking_ = false, lastAsked_ = t;
      return;
    }
    if (t - askedAt_ < limit)
      return;
    std::string silent;
    int count = 0;
    for (int r = 0; r < ranks_; ++r)
      if (!answered_[std::size_t(r)])
        silent += (count++ ? ", " : "") + std::to_string(r);
    std::fprintf(stderr,
                 "%s: error: rank %s stopped answering: no answer in %.0f s, while rank %d made "
                 "no progress for %.0f s (the MPI watchdog: --watchdog SECONDS, 0 turns it off); "
                 "ending the job\n",
                 program_.c_str(), silent.c_str(), t - askedAt_, rank_,
                 t - lastProgress.load(std::memory_order_relaxed));
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, 1);
  }

  std::optional<double> fixed_;
  std::string program_;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int rank_ = 0, ranks_ = 1;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  // The watchdog thread's own.
  bool asking_ = false;
  double askedAt_ = 0.0, lastAsked_ = 0.0;
  std::uint64_t round_ = 0;
  std::vector<bool> answered_;
  std::list<Pending> sent_; ///< a list: the buffers stay where MPI_Isend saw them
};

// Never destroyed: a main that calls exit() must not join (or terminate) it.
Watchdog *watchdog = nullptr;

} // namespace

int watchdogThreadLevel(std::optional<double> seconds) {
  return seconds && *seconds == 0.0 ? MPI_THREAD_FUNNELED : MPI_THREAD_MULTIPLE;
}

void startWatchdog(std::optional<double> seconds, int providedThreadLevel, std::string program) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (ranks < 2 || watchdogThreadLevel(seconds) != MPI_THREAD_MULTIPLE)
    return;
  if (providedThreadLevel < MPI_THREAD_MULTIPLE) {
    if (rank == 0)
      std::fprintf(stderr,
                   "%s: warning: this MPI library offers no MPI_THREAD_MULTIPLE: no "
                   "watchdog (a stopped rank will hang the job)\n",
                   program.c_str());
    return;
  }
  watchdog = new Watchdog(seconds, std::move(program));
}

void stopWatchdog() {
  if (!watchdog)
    return;
  // No rank stops answering while another may still ask: all are here first.
  MPI_Barrier(MPI_COMM_WORLD);
  watchdog->stop();
}

void progressed() {
  const double t = now(), gap = t - lastProgress.load(std::memory_order_relaxed);
  if (gap > longestGap.load(std::memory_order_relaxed))
    longestGap.store(gap, std::memory_order_relaxed);
  lastProgress.store(t, std::memory_order_relaxed);
}

} // namespace wash::mpi
