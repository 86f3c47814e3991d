//===- wash/detail/search.hpp - which particles are neighbours -*- C++ -*-===//
//
// A simulation chooses one neighbour rule in main (docs/semantics.md):
//  - set_influence_radius(r): j is a neighbour of i when |x_j - x_i| <= r,
//    neighbours in canonical cell order (neighbour_search.hpp);
//  - set_smoothing_length_support(k): when |x_j - x_i| <= k * h_i, with h_i
//    particle i's smoothing length when the force kernel starts, neighbours in
//    ascending id order (then the order cannot depend on any grid);
//  - set_smoothing_length_support(k, Support::Symmetric): when
//    |x_j - x_i|^2 <= (k * max(h_i, h_j))^2, in ascending id order: the pair
//    radius is the larger of the two support radii (k * max(h_i, h_j) equals
//    max(k * h_i, k * h_j) in double, multiplication by k > 0 being monotone).
// Every runtime computes the support radius k * h_i and the pair radius
// exactly as below.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/detail/box.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace wash::detail {

struct SearchRule {
  std::optional<double> radius;  ///< set_influence_radius
  std::optional<double> support; ///< set_smoothing_length_support
  bool symmetric = false;        ///< ... with Support::Symmetric

  bool perParticle() const { return support.has_value(); }

  /// "" if main chose exactly one rule, else what is wrong.
  std::string check() const {
    if (radius && support)
      return "both set_influence_radius and set_smoothing_length_support were called; a "
             "simulation uses one neighbour rule";
    if (!radius && !support)
      return "no neighbour rule: call wash::set_influence_radius or "
             "wash::set_smoothing_length_support before start()";
    return "";
  }

  /// For the run header: "influence radius 0.35" or "support radius 2h (...)".
  std::string describe() const {
    char text[96];
    if (support && symmetric)
      std::snprintf(text, sizeof text,
                    "support radius %gh (pairs within the larger smoothing length)", *support);
    else if (support)
      std::snprintf(text, sizeof text, "support radius %gh (per-particle smoothing length)",
                    *support);
    else
      std::snprintf(text, sizeof text, "influence radius %g", radius.value_or(0.0));
    return text;
  }
};

/// The support radius of a particle with smoothing length h.
inline double supportRadius(double factor, double h) { return factor * h; }

/// The pair radius of the symmetric rule: the larger support radius.
inline double pairRadius(double radiusI, double radiusJ) { return std::max(radiusI, radiusJ); }

/// "" if a particle's smoothing length can define a search, else what is wrong.
inline std::string checkSmoothingLength(double h) {
  if (!(h >= 0.0) || !std::isfinite(h))
    return "smoothing length " + std::to_string(h) +
           " cannot define a neighbour search (it must be finite and not negative)";
  return "";
}

/// "" if a periodic box is long enough for the largest support radius.
inline std::string checkPeriodicSupport(const Box &box, int dims, double largestSupport) {
  for (int a = 0; a < dims; ++a)
    if (box.defined && box.periodic[a] && !(box.length(a) > 2.0 * largestSupport))
      return "a support radius of " + std::to_string(largestSupport) +
             " is more than half the periodic box (axis " + std::to_string(a) +
             "); smoothing lengths grew too large for this box";
  return "";
}

} // namespace wash::detail
