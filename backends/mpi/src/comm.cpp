#include <wash/mpi/comm.hpp>
#include <wash/mpi/watchdog.hpp>

#include <mpi.h>

#include <limits>
#include <stdexcept>

namespace wash::mpi {
namespace {

int toInt(std::size_t n) {
  if (n > std::size_t(std::numeric_limits<int>::max()))
    throw std::length_error("wash mpi: a message exceeds 2 GiB; use more ranks");
  return int(n);
}

template <typename T> MPI_Datatype type();
template <> MPI_Datatype type<std::uint64_t>() { return MPI_UINT64_T; }
template <> MPI_Datatype type<double>() { return MPI_DOUBLE; }

template <typename T> std::vector<T> gatherAll(const std::vector<T> &local) {
  int n = toInt(local.size());
  std::vector<int> counts(ranks()), displs(ranks());
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (int r = 0; r < ranks(); ++r) {
    displs[r] = toInt(total);
    total += counts[r];
  }
  std::vector<T> all(total);
  MPI_Allgatherv(local.data(), n, type<T>(), all.data(), counts.data(), displs.data(), type<T>(),
                 MPI_COMM_WORLD);
  progressed();
  return all;
}

template <typename T> T reduce(T v, MPI_Op op) {
  T out = 0;
  MPI_Allreduce(&v, &out, 1, type<T>(), op, MPI_COMM_WORLD);
  progressed();
  return out;
}

} // namespace

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

Traffic &traffic() {
  static Traffic t;
  return t;
}

std::vector<std::size_t> alltoallCounts(const std::vector<std::size_t> &counts) {
  std::vector<std::uint64_t> out(counts.size()), in(counts.begin(), counts.end());
  MPI_Alltoall(in.data(), 1, MPI_UINT64_T, out.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD);
  progressed();
  return {out.begin(), out.end()};
}

std::vector<char> alltoallv(const std::vector<std::vector<char>> &send,
                            const std::vector<std::size_t> &recvBytes, std::uint64_t &counter) {
  std::vector<char> flat;
  std::vector<std::size_t> sendBytes;
  for (const std::vector<char> &bytes : send) {
    flat.insert(flat.end(), bytes.begin(), bytes.end());
    sendBytes.push_back(bytes.size());
  }
  return alltoallv(flat, sendBytes, recvBytes, counter);
}

std::vector<char> alltoallv(const std::vector<char> &flat,
                            const std::vector<std::size_t> &sendBytes,
                            const std::vector<std::size_t> &recvBytes, std::uint64_t &counter) {
  const int n = ranks(), me = rank();
  std::vector<int> sc(n), sd(n), rc(n), rd(n);
  std::vector<char> recv;
  std::size_t sent = 0, total = 0;
  for (int r = 0; r < n; ++r) {
    sd[r] = toInt(sent);
    sc[r] = toInt(sendBytes[r]);
    sent += sendBytes[r];
    if (r != me)
      counter += sendBytes[r];
    rd[r] = toInt(total);
    rc[r] = toInt(recvBytes[r]);
    total += recvBytes[r];
  }
  recv.resize(total);
  MPI_Alltoallv(flat.data(), sc.data(), sd.data(), MPI_BYTE, recv.data(), rc.data(), rd.data(),
                MPI_BYTE, MPI_COMM_WORLD);
  progressed();
  return recv;
}

std::uint64_t allreduceSum(std::uint64_t v) { return reduce(v, MPI_SUM); }
std::uint64_t allreduceMax(std::uint64_t v) { return reduce(v, MPI_MAX); }
std::uint64_t allreduceMin(std::uint64_t v) { return reduce(v, MPI_MIN); }
double allreduceMax(double v) { return reduce(v, MPI_MAX); }
double allreduceSum(double v) { return reduce(v, MPI_SUM); }
std::vector<std::uint64_t> allgatherv(const std::vector<std::uint64_t> &l) { return gatherAll(l); }
std::vector<double> allgatherv(const std::vector<double> &l) { return gatherAll(l); }

detail::ExactSum allreduceSum(const detail::ExactSum &local) {
  const detail::ExactSum::State mine = local.state();
  detail::ExactSum::State all{};
  MPI_Allreduce(mine.data(), all.data(), int(all.size()), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  progressed();
  traffic().sums += sizeof mine;
  detail::ExactSum total;
  total.merge(all);
  return total;
}

double allreduceMinMax(const std::vector<double> &values, const std::vector<std::uint32_t> &rows,
                       detail::ReduceOp op) {
  std::vector<double> mine; // order does not matter for min and max
  for (std::uint32_t p : rows)
    mine.push_back(values[p]);
  return reduce(detail::reduceInIdOrder(mine, op), op == detail::ReduceOp::Min ? MPI_MIN : MPI_MAX);
}

namespace {

class WriterProcesses final : public detail::Processes {
public:
  WriterProcesses() { MPI_Comm_dup(MPI_COMM_WORLD, &comm_); }
  int rank() const override { return mpi::rank(); }
  int count() const override { return ranks(); }
  std::vector<std::uint64_t> allgather(std::uint64_t value) const override {
    std::vector<std::uint64_t> all(static_cast<std::size_t>(ranks()));
    MPI_Allgather(&value, 1, MPI_UINT64_T, all.data(), 1, MPI_UINT64_T, comm_);
    progressed();
    return all;
  }
  std::vector<char> request(int from) const override {
    MPI_Send(nullptr, 0, MPI_BYTE, from, askTag, comm_);
    MPI_Status status;
    MPI_Probe(from, dataTag, comm_, &status);
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::vector<char> message(static_cast<std::size_t>(bytes));
    MPI_Recv(message.data(), bytes, MPI_BYTE, from, dataTag, comm_, MPI_STATUS_IGNORE);
    progressed();
    return message;
  }
  void answer(const std::vector<char> &message) const override {
    MPI_Recv(nullptr, 0, MPI_BYTE, 0, askTag, comm_, MPI_STATUS_IGNORE);
    MPI_Send(message.data(), toInt(message.size()), MPI_BYTE, 0, dataTag, comm_);
    progressed();
  }

private:
  static constexpr int askTag = 1, dataTag = 2;
  MPI_Comm comm_;
};

} // namespace

const detail::Processes &writerProcesses() {
  static const WriterProcesses processes;
  return processes;
}

} // namespace wash::mpi
