//===- wash/backend/frame_builder.hpp - output frames from columns -*- C++ -*-===//
#pragma once

#include <wash/backend/columns.hpp>
#include <wash/detail/frame.hpp>
#include <wash/vec.hpp>

#include <string>

namespace wash::backend {

/// Builds the writers' Frame from structure-of-arrays columns, in the order the
/// generated code adds them (the output order of docs/semantics.md).
class FrameBuilder {
public:
  /// A frame of every particle, or of the given rows only (an MPI rank's own).
  FrameBuilder(int dimensions, const Column<std::uint64_t> &ids,
               const std::vector<Index> *rows = nullptr)
      : rows_(rows) {
    frame_.dimensions = dimensions;
    forEachRow(ids.size(), [&](std::size_t p) { frame_.ids.push_back(ids[p]); });
  }
  template <typename T> void scalar(const char *name, const Column<T> &column) {
    detail::Column out{name, 1, {}};
    forEachRow(column.size(), [&](std::size_t p) { out.values.push_back(double(column[p])); });
    frame_.columns.push_back(std::move(out));
  }
  template <typename T, int D> void vector(const char *name, const Column<Vec<T, D>> &column) {
    detail::Column out{name, D, {}};
    forEachRow(column.size(), [&](std::size_t p) {
      for (int a = 0; a < D; ++a)
        out.values.push_back(double(column[p].at(a)));
    });
    frame_.columns.push_back(std::move(out));
  }
  /// A field the program never writes (it has no storage): zeros.
  void zeros(const char *name, int components) {
    frame_.columns.push_back({name, components, std::vector<double>(frame_.size() * components)});
  }
  /// A typed simulation's type names, by index (VTK field data).
  void typeNames(std::vector<std::string> names) { frame_.typeNames = std::move(names); }
  /// The column added last goes to frames only, not to --dump (acc).
  void frameOnly() { frame_.columns.back().inDump = false; }
  detail::Frame take() { return std::move(frame_); }

private:
  template <typename F> void forEachRow(std::size_t size, F f) const {
    if (!rows_)
      for (std::size_t p = 0; p < size; ++p)
        f(p);
    else
      for (Index p : *rows_)
        f(p);
  }

  const std::vector<Index> *rows_;
  detail::Frame frame_;
};

} // namespace wash::backend
