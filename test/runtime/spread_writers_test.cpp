// The chunked writers of a frame spread over processes, with threads as the
// processes: rank 0's file must be the bytes writers.hpp writes for the whole
// frame, however the rows are spread and across many chunks per process.
#include <wash/detail/spread_writers.hpp>

#include <gtest/gtest.h>

#include <barrier>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <sstream>
#include <thread>

using namespace wash::detail;

namespace {

/// The request-answer exchange and allgather of detail::Processes, in memory.
struct Exchange {
  explicit Exchange(int n) : sync(n), asks(n), mail(n), slots(n) {}
  std::barrier<> sync;
  std::mutex m;
  std::condition_variable cv;
  std::vector<int> asks;
  std::vector<std::deque<std::vector<char>>> mail;
  std::vector<std::uint64_t> slots;
};

class ThreadProcess final : public Processes {
public:
  ThreadProcess(Exchange &x, int rank) : x_(x), rank_(rank) {}
  int rank() const override { return rank_; }
  int count() const override { return int(x_.asks.size()); }
  std::vector<std::uint64_t> allgather(std::uint64_t value) const override {
    x_.slots[std::size_t(rank_)] = value;
    x_.sync.arrive_and_wait();
    std::vector<std::uint64_t> all = x_.slots;
    x_.sync.arrive_and_wait();
    return all;
  }
  std::vector<char> request(int from) const override {
    std::unique_lock lock(x_.m);
    ++x_.asks[std::size_t(from)];
    x_.cv.notify_all();
    x_.cv.wait(lock, [&] { return !x_.mail[std::size_t(from)].empty(); });
    std::vector<char> message = std::move(x_.mail[std::size_t(from)].front());
    x_.mail[std::size_t(from)].pop_front();
    return message;
  }
  void answer(const std::vector<char> &message) const override {
    std::unique_lock lock(x_.m);
    x_.cv.wait(lock, [&] { return x_.asks[std::size_t(rank_)] > 0; });
    --x_.asks[std::size_t(rank_)];
    // At most one answer waits for rank 0 (docs of Processes::answer).
    EXPECT_TRUE(x_.mail[std::size_t(rank_)].empty());
    x_.mail[std::size_t(rank_)].push_back(message);
    x_.cv.notify_all();
  }

private:
  Exchange &x_;
  int rank_;
};

/// A 3D frame of n rows with scalar and vector columns; ids a permutation.
Frame frame(std::size_t n) {
  Frame f;
  f.dimensions = 3;
  f.columns = {{"pos", 3, {}}, {"vel", 3, {}}, {"density", 1, {}}, {"acc", 3, {}, false}};
  for (std::size_t p = 0; p < n; ++p) {
    f.ids.push_back((p * 7919) % n);
    for (Column &c : f.columns)
      for (int k = 0; k < c.components; ++k)
        c.values.push_back(1.0 / double(p + 1) + double(k) * 0.1 - double(c.name.size()));
  }
  return f;
}

/// Rows `owner(p) == r` of `whole`, in order.
Frame rowsOf(const Frame &whole, int r, int ranks) {
  Frame f;
  f.dimensions = whole.dimensions;
  for (const Column &c : whole.columns)
    f.columns.push_back({c.name, c.components, {}, c.inDump});
  for (std::size_t p = 0; p < whole.size(); ++p) {
    if (int((p / 700 + p % 3) % std::size_t(ranks)) != r) // uneven runs, like cells
      continue;
    f.ids.push_back(whole.ids[p]);
    for (std::size_t c = 0; c < f.columns.size(); ++c) {
      const Column &from = whole.columns[c];
      for (int k = 0; k < from.components; ++k)
        f.columns[c].values.push_back(from.values[p * from.components + k]);
    }
  }
  return f;
}

/// Rank 0's file when `ranks` threads write `whole` spread so with `write`.
template <typename Write> std::string spreadFile(const Frame &whole, int ranks, Write write) {
  Exchange x(ranks);
  std::vector<Frame> parts;
  for (int r = 0; r < ranks; ++r)
    parts.push_back(rowsOf(whole, r, ranks));
  std::ostringstream out;
  std::vector<std::thread> threads;
  for (int r = 0; r < ranks; ++r)
    threads.emplace_back([&, r] {
      ThreadProcess me(x, r);
      write(me, parts[std::size_t(r)], r == 0 ? &out : nullptr);
    });
  for (std::thread &t : threads)
    t.join();
  return out.str();
}

Frame inRankOrder(const Frame &whole, int ranks) {
  Frame all = rowsOf(whole, 0, ranks);
  for (int r = 1; r < ranks; ++r) {
    Frame part = rowsOf(whole, r, ranks);
    all.ids.insert(all.ids.end(), part.ids.begin(), part.ids.end());
    for (std::size_t c = 0; c < all.columns.size(); ++c)
      all.columns[c].values.insert(all.columns[c].values.end(), part.columns[c].values.begin(),
                                   part.columns[c].values.end());
  }
  return all;
}

} // namespace

TEST(SpreadWriters, CsvIsTheWholeFramesSortedById) {
  const Frame whole = frame(3000);
  for (int ranks : {1, 2, 3, 5}) {
    std::ostringstream want;
    writeCsv(whole, want);
    EXPECT_EQ(spreadFile(whole, ranks,
                         [](const Processes &p, const Frame &local, std::ostream *out) {
                           // 20 rows a chunk: dozens of chunks per process.
                           writeCsvSpread(p, local, dumpColumns(local), out, 20 * 64);
                         }),
              want.str())
        << ranks << " ranks";
  }
}

TEST(SpreadWriters, VtpIsTheWholeFramesInRankOrder) {
  const Frame whole = frame(3000);
  for (bool ascii : {false, true})
    for (int ranks : {2, 3}) {
      const VtpOptions options{.ascii = ascii, .time = 0.25};
      const Frame all = inRankOrder(whole, ranks);
      std::ostringstream want;
      writeVtp(all, frameColumns(all, {}), options, want);
      EXPECT_EQ(spreadFile(whole, ranks,
                           [&](const Processes &p, const Frame &local, std::ostream *out) {
                             writeVtpSpread(p, local, frameColumns(local, {}), options, out,
                                            1000); // 41 points, 125 densities a chunk
                           }),
                want.str())
          << ranks << " ranks, ascii " << ascii;
    }
}
