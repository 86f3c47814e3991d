#include <wash/mpi/comm.hpp>

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
  return all;
}

template <typename T> T reduce(T v, MPI_Op op) {
  T out = 0;
  MPI_Allreduce(&v, &out, 1, type<T>(), op, MPI_COMM_WORLD);
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
  return {out.begin(), out.end()};
}

std::vector<char> alltoallv(const std::vector<std::vector<char>> &send,
                            const std::vector<std::size_t> &recvBytes, std::uint64_t &counter) {
  const int n = ranks(), me = rank();
  std::vector<int> sc(n), sd(n), rc(n), rd(n);
  std::vector<char> flat, recv;
  std::size_t total = 0;
  for (int r = 0; r < n; ++r) {
    sd[r] = toInt(flat.size());
    sc[r] = toInt(send[r].size());
    flat.insert(flat.end(), send[r].begin(), send[r].end());
    if (r != me)
      counter += send[r].size();
    rd[r] = toInt(total);
    rc[r] = toInt(recvBytes[r]);
    total += recvBytes[r];
  }
  recv.resize(total);
  MPI_Alltoallv(flat.data(), sc.data(), sd.data(), MPI_BYTE, recv.data(), rc.data(), rd.data(),
                MPI_BYTE, MPI_COMM_WORLD);
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

detail::Frame gatherFrame(const detail::Frame &local) {
  // Every rank has the same columns in the same order; gather each to rank 0.
  auto gather = [](const auto &values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    int n = toInt(values.size());
    std::vector<int> counts(ranks()), displs(ranks());
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::size_t total = 0;
    for (int r = 0; r < ranks(); ++r) {
      displs[r] = toInt(total);
      total += counts[r];
    }
    std::vector<T> all(rank() == 0 ? total : 0);
    MPI_Gatherv(values.data(), n, type<T>(), all.data(), counts.data(), displs.data(), type<T>(), 0,
                MPI_COMM_WORLD);
    return all;
  };
  detail::Frame all;
  all.dimensions = local.dimensions;
  all.typeNames = local.typeNames; // every rank's are the same
  all.ids = gather(local.ids);
  for (const detail::Column &c : local.columns)
    all.columns.push_back({c.name, c.components, gather(c.values), c.inDump});
  if (rank() != 0)
    return {};
  return all;
}

} // namespace wash::mpi
