//===- wash/detail/processes.hpp - the processes a run is spread over -*- C++ -*-===//
//
// What the writers need of a run whose particles are spread over processes
// (the MPI backend) to write its frames through rank 0 in bounded chunks: the
// shared runtime knows no MPI, the MPI backend implements this interface.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cstdint>
#include <vector>

namespace wash::detail {

class Processes {
public:
  virtual ~Processes() = default;
  virtual int rank() const = 0;
  virtual int count() const = 0;
  /// Collective: every process's value, on every process.
  virtual std::vector<std::uint64_t> allgather(std::uint64_t value) const = 0;
  /// Rank 0: asks process `from` for its next message and waits for it.
  virtual std::vector<char> request(int from) const = 0;
  /// A process other than 0: waits until rank 0 asks, then sends `message`.
  /// A process holds at most one message not yet sent, rank 0 one per process.
  virtual void answer(const std::vector<char> &message) const = 0;
};

/// The run's processes, set by the MPI backend's entry point; null elsewhere.
const Processes *&processes();

/// Whether this process writes the files a frame goes to (CSV, VTK, --dump):
/// rank 0, or the one process of a run that is not distributed.
inline bool writesFiles() { return !processes() || processes()->rank() == 0; }

} // namespace wash::detail
