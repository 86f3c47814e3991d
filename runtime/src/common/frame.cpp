#include <wash/detail/frame.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace wash::detail {

std::vector<std::size_t> Frame::orderById() const {
  std::vector<std::size_t> order(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  return order;
}

std::vector<std::string> csvHeaders(const Column &column) {
  if (column.components == 1)
    return {column.name};
  static const char axes[] = {'x', 'y', 'z'};
  std::vector<std::string> names;
  for (int c = 0; c < column.components; ++c) {
    if (column.name == "pos")
      names.push_back(std::string(1, axes[c]));
    else if (column.name == "vel")
      names.push_back(std::string("v") + axes[c]);
    else
      names.push_back(column.name + "_" + axes[c]);
  }
  return names;
}

std::string findNonFinite(const Frame &frame) {
  for (const Column &column : frame.columns) {
    for (std::size_t k = 0; k < column.values.size(); ++k) {
      if (std::isfinite(column.values[k]))
        continue;
      return nonFiniteMessage(column.name, frame.ids[k / column.components], column.values[k]);
    }
  }
  return "";
}

std::string nonFiniteMessage(const std::string &field, std::uint64_t id, double value) {
  std::ostringstream msg;
  msg << "field '" << field << "' of particle " << id << " is " << value;
  return msg.str();
}

} // namespace wash::detail
