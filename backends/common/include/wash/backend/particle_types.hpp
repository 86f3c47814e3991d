//===- wash/backend/particle_types.hpp - rows of each particle type -*- C++ -*-===//
//
// A kernel registered for one particle type loops over that type's rows
// only, never testing the others: the driver rebuilds them from the type
// column after every neighbour search (whose sort moves the rows) and after
// every kernel that sets types (docs/backends.md).
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/backend/columns.hpp>

#include <cstdint>
#include <vector>

namespace wash::backend {

class TypeRows {
public:
  explicit TypeRows(std::size_t types) : rows_(types) {}

  /// The real particles' rows by type, each ascending (as `owned` is).
  void rebuild(const Column<std::uint32_t> &type, const std::vector<Index> &owned) {
    counts_.assign(rows_.size(), 0);
    for (Index i : owned)
      ++counts_[type[i]];
    for (std::size_t t = 0; t < rows_.size(); ++t) {
      rows_[t].resize(counts_[t]);
      counts_[t] = 0;
    }
    for (Index i : owned) {
      const std::uint32_t t = type[i];
      rows_[t][counts_[t]++] = i;
    }
  }

  const std::vector<Index> &of(std::uint32_t t) const { return rows_[t]; }

private:
  std::vector<std::vector<Index>> rows_;
  std::vector<std::size_t> counts_;
};

} // namespace wash::backend
