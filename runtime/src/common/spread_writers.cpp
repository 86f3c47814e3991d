#include <wash/detail/spread_writers.hpp>

#include <algorithm>
#include <cstring>
#include <functional>
#include <queue>
#include <utility>

namespace wash::detail {
namespace {

std::size_t widthOf(const Columns &columns) {
  std::size_t width = 0;
  for (const Column *column : columns)
    width += std::size_t(column->components);
  return width;
}

/// A chunk of CSV rows: the row count k, k ids, then k rows of values.
void packRows(const Frame &frame, const Columns &columns, const std::vector<std::size_t> &order,
              std::size_t from, std::size_t to, std::vector<char> &message) {
  const std::uint64_t k = to - from;
  std::vector<std::uint64_t> ids;
  std::vector<double> values;
  for (std::size_t r = from; r < to; ++r) {
    const std::size_t p = order[r];
    ids.push_back(frame.ids[p]);
    for (const Column *column : columns)
      for (int c = 0; c < column->components; ++c)
        values.push_back(column->values[p * column->components + c]);
  }
  message.resize(sizeof k + ids.size() * 8 + values.size() * 8);
  char *at = message.data();
  std::memcpy(at, &k, sizeof k);
  std::memcpy(at + sizeof k, ids.data(), ids.size() * 8);
  std::memcpy(at + sizeof k + ids.size() * 8, values.data(), values.size() * 8);
}

/// Rank 0's reader of one process's rows in id order, a chunk at a time.
class RowSource {
public:
  RowSource(std::function<void(std::vector<char> &)> next, std::uint64_t rows, std::size_t width)
      : next_(std::move(next)), left_(rows), width_(width) {}
  /// False once every row was read.
  bool advance() {
    if (++at_ < inChunk_)
      return true;
    if (left_ == 0)
      return false;
    next_(message_);
    std::memcpy(&inChunk_, message_.data(), sizeof inChunk_);
    ids_.resize(inChunk_);
    values_.resize(inChunk_ * width_);
    std::memcpy(ids_.data(), message_.data() + 8, inChunk_ * 8);
    std::memcpy(values_.data(), message_.data() + 8 + inChunk_ * 8, values_.size() * 8);
    left_ -= std::min<std::uint64_t>(left_, inChunk_);
    at_ = 0;
    return inChunk_ > 0;
  }
  std::uint64_t id() const { return ids_[at_]; }
  const double *values() const { return values_.data() + at_ * width_; }

private:
  std::function<void(std::vector<char> &)> next_;
  std::uint64_t left_;
  std::size_t width_;
  std::vector<char> message_;
  std::vector<std::uint64_t> ids_;
  std::vector<double> values_;
  std::uint64_t inChunk_ = 0, at_ = 0;
};

std::size_t chunkRows(std::size_t chunkBytes, std::size_t rowBytes) {
  return std::max<std::size_t>(1, chunkBytes / rowBytes);
}

std::vector<char> packDoubles(const std::vector<double> &values) {
  std::vector<char> message(values.size() * 8);
  std::memcpy(message.data(), values.data(), message.size());
  return message;
}

} // namespace

void writeCsvSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    std::ostream *out, std::size_t chunkBytes) {
  const std::vector<std::uint64_t> counts = processes.allgather(local.size());
  const std::vector<std::size_t> order = local.orderById();
  const std::size_t width = widthOf(columns);
  // Rank 0 holds a chunk of every process at once (the merge): smaller
  // chunks on many processes keep that under spreadMergeBytes.
  const std::size_t share = spreadMergeBytes / std::size_t(processes.count());
  const std::size_t rows = chunkRows(std::min(chunkBytes, std::max(share, spreadMinChunkBytes)),
                                     8 + 8 * width);
  std::vector<char> message;
  if (processes.rank() != 0) {
    for (std::size_t from = 0; from < order.size(); from += rows) {
      packRows(local, columns, order, from, std::min(order.size(), from + rows), message);
      processes.answer(message);
    }
    return;
  }
  std::vector<RowSource> sources;
  std::size_t ownFrom = 0;
  sources.emplace_back(
      [&](std::vector<char> &m) {
        const std::size_t to = std::min(order.size(), ownFrom + rows);
        packRows(local, columns, order, ownFrom, to, m);
        ownFrom = to;
      },
      counts[0], width);
  for (int r = 1; r < processes.count(); ++r)
    sources.emplace_back([&processes, r](std::vector<char> &m) { m = processes.request(r); },
                         counts[std::size_t(r)], width);
  // The k-way merge: the smallest id at the head of any process's rows next.
  using Head = std::pair<std::uint64_t, std::size_t>;
  std::priority_queue<Head, std::vector<Head>, std::greater<>> heads;
  for (std::size_t s = 0; s < sources.size(); ++s)
    if (sources[s].advance())
      heads.push({sources[s].id(), s});
  writeCsvHeader(columns, *out);
  std::string lines;
  while (!heads.empty()) {
    const std::size_t s = heads.top().second;
    heads.pop();
    appendCsvRow(lines, sources[s].id(), sources[s].values(), width);
    if (lines.size() >= 1 << 16) {
      *out << lines;
      lines.clear();
    }
    if (sources[s].advance())
      heads.push({sources[s].id(), s});
  }
  *out << lines;
}

void writeVtpSpread(const Processes &processes, const Frame &local, const Columns &columns,
                    const VtpOptions &options, std::ostream *out, std::size_t chunkBytes) {
  const std::vector<std::uint64_t> counts = processes.allgather(local.size());
  const std::vector<VtpArray> arrays = vtpArrays(local, columns);
  std::vector<double> chunk;
  auto rowsOf = [&](std::size_t a) {
    return chunkRows(chunkBytes, 8 * std::size_t(arrays[a].components));
  };
  auto valuesOf = [&](std::size_t a, std::size_t from) {
    chunk.clear();
    vtpArrayValues(local, arrays[a], from, std::min(local.size(), from + rowsOf(a)), chunk);
  };
  if (processes.rank() != 0) {
    // The order rank 0 reads them in: array by array, a chunk at a time.
    for (std::size_t a = 0; a < arrays.size(); ++a)
      for (std::size_t from = 0; from < local.size(); from += rowsOf(a)) {
        valuesOf(a, from);
        processes.answer(packDoubles(chunk));
      }
    return;
  }
  std::uint64_t total = 0;
  for (std::uint64_t n : counts)
    total += n;
  std::vector<double> remote;
  auto feed = [&](std::size_t a, const VtpEmit &emit) {
    for (std::size_t from = 0; from < local.size(); from += rowsOf(a)) {
      valuesOf(a, from);
      emit(chunk.data(), chunk.size());
    }
    for (int r = 1; r < processes.count(); ++r)
      for (std::uint64_t from = 0; from < counts[std::size_t(r)]; from += rowsOf(a)) {
        const std::vector<char> message = processes.request(r);
        remote.resize(message.size() / 8);
        std::memcpy(remote.data(), message.data(), message.size());
        emit(remote.data(), remote.size());
      }
  };
  writeVtp(total, arrays, options, feed, *out);
}

} // namespace wash::detail
