//===- wash/detail/box.hpp - the simulation box and periodic images -*- C++ -*-===//
//
// The arithmetic every runtime must do identically for periodic axes
// (docs/semantics.md): wrapping a coordinate into [lo, hi), and choosing which
// image of a particle is the neighbour of another.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace wash::detail {

struct Box {
  bool defined = false; ///< set_bounding_box was called
  std::array<double, 3> lo{}, hi{};
  std::array<bool, 3> periodic{};

  bool anyPeriodic() const { return periodic[0] || periodic[1] || periodic[2]; }
  double length(int a) const { return hi[a] - lo[a]; }

  /// x wrapped into [lo, hi) on periodic axis a: x - L floor((x - lo) / L);
  /// a coordinate already inside is returned unchanged, and a non-finite one
  /// becomes NaN (never lo: the finite checks must see it).
  double wrap(double x, int a) const {
    const double L = length(a);
    double r = x - L * std::floor((x - lo[a]) / L);
    return !(r >= hi[a]) ? r : lo[a]; // rounding can land exactly on hi
  }

  /// The image of coordinate xj (of particle j) to use as a neighbour of a
  /// particle at xi on periodic axis a: -1 (xj - L), 0 (xj) or +1 (xj + L):
  /// xj itself when |xj - xi| <= L/2, else the image on xi's side.
  int image(double xj, double xi, int a) const {
    const double d = xj - xi, half = 0.5 * length(a);
    if (d > half)
      return -1;
    if (d < -half)
      return 1;
    return 0;
  }

  /// xj moved by k box lengths on axis a, computed as every runtime must.
  double shifted(double xj, int k, int a) const {
    return k == 0 ? xj : k > 0 ? xj + length(a) : xj - length(a);
  }
};

/// Fills box from the API's lists; false if they do not fit `dims`.
inline bool setBox(Box &box, int dims, const std::vector<double> &lo, const std::vector<double> &hi,
                   const std::vector<bool> &periodic) {
  if (int(lo.size()) != dims || int(hi.size()) != dims || int(periodic.size()) != dims)
    return false;
  for (int a = 0; a < dims; ++a) {
    if (!(hi[a] > lo[a]) || !std::isfinite(lo[a]) || !std::isfinite(hi[a]))
      return false;
    box.lo[a] = lo[a];
    box.hi[a] = hi[a];
    box.periodic[a] = periodic[a];
  }
  box.defined = true;
  return true;
}

/// "" if the box suits the influence radius, else what is wrong.
inline std::string checkBox(const Box &box, int dims, double radius) {
  if (!box.defined)
    return "";
  for (int a = 0; a < dims; ++a) {
    if (!(box.hi[a] > box.lo[a]))
      return "the bounding box is empty on axis " + std::to_string(a);
    if (box.periodic[a] && !(box.length(a) > 2.0 * radius))
      return "a periodic box must be longer than twice the influence radius (axis " +
             std::to_string(a) + ")";
  }
  return "";
}

} // namespace wash::detail
