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
  FrameBuilder(int dimensions, const Column<std::uint64_t> &ids) {
    frame_.dimensions = dimensions;
    frame_.ids = ids;
  }
  template <typename T> void scalar(const char *name, const Column<T> &column) {
    frame_.columns.push_back({name, 1, std::vector<double>(column.begin(), column.end())});
  }
  template <typename T, int D> void vector(const char *name, const Column<Vec<T, D>> &column) {
    detail::Column out{name, D, {}};
    out.values.reserve(column.size() * D);
    for (const Vec<T, D> &v : column)
      for (int a = 0; a < D; ++a)
        out.values.push_back(double(v.at(a)));
    frame_.columns.push_back(std::move(out));
  }
  /// A field the program never writes (it has no storage): zeros.
  void zeros(const char *name, int components) {
    frame_.columns.push_back({name, components, std::vector<double>(frame_.size() * components)});
  }
  detail::Frame take() { return std::move(frame_); }

private:
  detail::Frame frame_;
};

} // namespace wash::backend
