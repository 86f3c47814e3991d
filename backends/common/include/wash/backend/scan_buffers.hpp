//===- wash/backend/scan_buffers.hpp - where a neighbour scan writes -*- C++ -*-===//
//
// An x86 core makes a load wait for an earlier store whose address has the
// same low 12 bits ("4K aliasing"). Every block of the vector scan loads a
// compaction table entry right after storing to the scan's buffers: where
// malloc happened to put those made the seed program anywhere from 0 to 35 %
// slower, from one run of the same binary to the next (docs/performance.md).
// So the tables take the first scanTableBytes of a page (scan_avx2.hpp checks
// that they fit), and the buffers start past them.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace wash::backend {

/// Entries a scan may write past the last neighbour kept: its buffer needs
/// room for the candidates plus this many.
inline constexpr std::size_t scanSlack = 4;

/// The page offsets [0, scanTableBytes) the vector scan's compaction tables
/// occupy.
inline constexpr std::size_t scanTableBytes = 1024;

/// The buffers a scan writes, one set per thread: the rows kept and their
/// (squared) distances, in one page-aligned block, the rows from page offset
/// scanTableBytes, the distances from the middle of the rest of a page: clear
/// of the tables for up to 188 neighbours (8-byte rows).
template <typename Ref> class ScanBuffers {
public:
  ScanBuffers() = default;
  ScanBuffers(const ScanBuffers &) = delete;
  ScanBuffers &operator=(const ScanBuffers &) = delete;
  ~ScanBuffers() { std::free(block_); }

  /// Room for n entries in each, plus the vector scan's whole last block.
  void reserve(std::size_t n) {
    n += scanSlack;
    if (n <= capacity_)
      return;
    const std::size_t capacity = std::max(n, 2 * capacity_);
    const std::size_t distAt = nextAt(rowsAt + capacity * sizeof(Ref), distOffset);
    const std::size_t bytes = (distAt + capacity * sizeof(double) + page - 1) / page * page;
    void *block = std::aligned_alloc(page, bytes);
    if (!block)
      throw std::bad_alloc();
    std::free(block_);
    block_ = block;
    rows_ = reinterpret_cast<Ref *>(static_cast<char *>(block) + rowsAt);
    dist_ = reinterpret_cast<double *>(static_cast<char *>(block) + distAt);
    capacity_ = capacity;
  }
  Ref *rows() const { return rows_; }
  double *distances() const { return dist_; }

private:
  static constexpr std::size_t page = 4096;
  static constexpr std::size_t rowsAt = scanTableBytes;
  static constexpr std::size_t distOffset = (scanTableBytes + page) / 2;
  /// The first position from `at` on that lies at `offset` within a page.
  static std::size_t nextAt(std::size_t at, std::size_t offset) {
    return (at + page - offset + page - 1) / page * page + offset - page;
  }
  void *block_ = nullptr;
  Ref *rows_ = nullptr;
  double *dist_ = nullptr;
  std::size_t capacity_ = 0;
};

} // namespace wash::backend
