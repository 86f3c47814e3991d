//===- wash/mpi/comm.hpp - the few MPI operations the MPI backend uses -*- C++ -*-===//
#pragma once

#include <wash/detail/exact_sum.hpp>
#include <wash/detail/frame.hpp>
#include <wash/detail/processes.hpp>
#include <wash/detail/reduction.hpp>

#include <cstdint>
#include <vector>

namespace wash::mpi {

int rank();
int ranks();

/// Bytes sent to other ranks so far, by purpose (for the end-of-run report).
struct Traffic {
  std::uint64_t halo = 0, migration = 0, sums = 0;
};
Traffic &traffic();

/// Sends send[r] to rank r and returns what each rank sent here, in rank
/// order; recvBytes[r] must be known (alltoallExchangeCounts gives it).
std::vector<char> alltoallv(const std::vector<std::vector<char>> &send,
                            const std::vector<std::size_t> &recvBytes, std::uint64_t &counter);
/// The same from one buffer: sendBytes[0] bytes for rank 0, then rank 1's...
/// (no copy of what is sent).
std::vector<char> alltoallv(const std::vector<char> &flat, const std::vector<std::size_t> &sendBytes,
                            const std::vector<std::size_t> &recvBytes, std::uint64_t &counter);
/// counts[r] -> what rank r sent to this one.
std::vector<std::size_t> alltoallCounts(const std::vector<std::size_t> &counts);

std::uint64_t allreduceSum(std::uint64_t v);
std::uint64_t allreduceMax(std::uint64_t v);
std::uint64_t allreduceMin(std::uint64_t v);
double allreduceMax(double v);
double allreduceSum(double v);
/// Every rank's `local`, concatenated in rank order, on every rank.
std::vector<std::uint64_t> allgatherv(const std::vector<std::uint64_t> &local);
std::vector<double> allgatherv(const std::vector<double> &local);

/// The exact sum of every rank's `local`: one MPI_Allreduce of their states
/// (ExactSum::State, integers that add), the same bytes however many values.
detail::ExactSum allreduceSum(const detail::ExactSum &local);
/// The Min or Max over all ranks of values[p] at this rank's positions `rows`.
double allreduceMinMax(const std::vector<double> &values, const std::vector<std::uint32_t> &rows,
                       detail::ReduceOp op);

/// The ranks as the writers see them (wash/detail/processes.hpp), on a
/// communicator of their own; after MPI_Init only.
const detail::Processes &writerProcesses();

} // namespace wash::mpi
