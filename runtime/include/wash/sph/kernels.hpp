//===- wash/sph/kernels.hpp - SPH smoothing kernels -------------*- C++ -*-===//
//
// Every kernel is a function of the distance r and the smoothing length h,
// q = r / h, with compact support `support * h` (the support radius): 2h for
// the cubic spline and the Wendland kernels, 3h for the quintic spline and the
// truncated Gaussian. W<D>(r, h) integrates to 1 over the D-dimensional ball of
// that radius; dWdr<D>(r, h) is its derivative in r (<= 0), so that
//   grad_i W(|x_i - x_j|, h) = (x_i - x_j) * (dWdr(r, h) / r)    (gradient()).
// D defaults to the program's dimension (wash::dimensions). Formulas and
// references: docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/wash.hpp>

#include <cmath>

namespace wash::sph {

/// grad_i W for the separation d = x_i - x_j of length r > 0.
template <typename V> V gradient(const V &d, double r, double dWdr) { return d * (dWdr / r); }

/// Cubic B-spline M4 (Monaghan & Lattanzio 1985), support 2h.
namespace cubic_spline {
inline constexpr double support = 2.0;
template <int D = wash::dimensions> double sigma(double h) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    return 10.0 / (7.0 * PI * h * h);
  else
    return 1.0 / (PI * h * h * h);
}
template <int D = wash::dimensions> double W(double r, double h) {
  double q = r / h, s = sigma<D>(h);
  if (q < 1.0)
    return s * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  if (q < 2.0)
    return s * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
  return 0.0;
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  double q = r / h, s = sigma<D>(h);
  if (q < 1.0)
    return s / h * (-3.0 * q + 2.25 * q * q);
  if (q < 2.0)
    return s / h * (-0.75 * (2.0 - q) * (2.0 - q));
  return 0.0;
}
} // namespace cubic_spline

/// Quintic B-spline M6 (Schoenberg 1946; Morris et al. 1997), support 3h.
namespace quintic_spline {
inline constexpr double support = 3.0;
template <int D = wash::dimensions> double sigma(double h) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    return 7.0 / (478.0 * PI * h * h);
  else
    return 1.0 / (120.0 * PI * h * h * h);
}
inline double pow4(double x) { return x * x * x * x; }
template <int D = wash::dimensions> double W(double r, double h) {
  double q = r / h, a = 3.0 - q, b = 2.0 - q, c = 1.0 - q, w = 0.0;
  if (q >= 3.0)
    return 0.0;
  w = a * pow4(a);
  if (q < 2.0)
    w -= 6.0 * b * pow4(b);
  if (q < 1.0)
    w += 15.0 * c * pow4(c);
  return sigma<D>(h) * w;
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  double q = r / h, a = 3.0 - q, b = 2.0 - q, c = 1.0 - q, w = 0.0;
  if (q >= 3.0)
    return 0.0;
  w = -5.0 * pow4(a);
  if (q < 2.0)
    w += 30.0 * pow4(b);
  if (q < 1.0)
    w -= 75.0 * pow4(c);
  return sigma<D>(h) / h * w;
}
} // namespace quintic_spline

/// Wendland C2 (Wendland 1995; Dehnen & Aly 2012), support 2h, s = 1 - q/2:
/// W = sigma s^4 (1 + 2q).
namespace wendland_c2 {
inline constexpr double support = 2.0;
template <int D = wash::dimensions> double W(double r, double h) {
  static_assert(D == 2 || D == 3);
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q;
  if constexpr (D == 2)
    return 7.0 / (4.0 * PI * h * h) * s * s * s * s * (1.0 + 2.0 * q);
  else
    return 21.0 / (16.0 * PI * h * h * h) * s * s * s * s * (1.0 + 2.0 * q);
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  static_assert(D == 2 || D == 3);
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q;
  if constexpr (D == 2)
    return -35.0 / (4.0 * PI * h * h * h) * q * s * s * s;
  else
    return -105.0 / (16.0 * PI * h * h * h * h) * q * s * s * s;
}
} // namespace wendland_c2

/// Wendland C4, support 2h: W = sigma s^6 (1 + 3q + 35/12 q^2).
namespace wendland_c4 {
inline constexpr double support = 2.0;
template <int D = wash::dimensions> double sigma(double h) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    return 9.0 / (4.0 * PI * h * h);
  else
    return 495.0 / (256.0 * PI * h * h * h);
}
template <int D = wash::dimensions> double W(double r, double h) {
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q, s2 = s * s;
  return sigma<D>(h) * s2 * s2 * s2 * (1.0 + 3.0 * q + 35.0 / 12.0 * q * q);
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q, s2 = s * s;
  return sigma<D>(h) / h * (-14.0 / 3.0) * q * (1.0 + 2.5 * q) * s2 * s2 * s;
}
} // namespace wendland_c4

/// Wendland C6, support 2h: W = sigma s^8 (1 + 4q + 25/4 q^2 + 4 q^3).
namespace wendland_c6 {
inline constexpr double support = 2.0;
template <int D = wash::dimensions> double sigma(double h) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    return 39.0 / (14.0 * PI * h * h);
  else
    return 1365.0 / (512.0 * PI * h * h * h);
}
template <int D = wash::dimensions> double W(double r, double h) {
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q, s4 = s * s * s * s;
  return sigma<D>(h) * s4 * s4 * (1.0 + 4.0 * q + 6.25 * q * q + 4.0 * q * q * q);
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  double q = r / h;
  if (q >= 2.0)
    return 0.0;
  double s = 1.0 - 0.5 * q, s4 = s * s * s * s;
  return sigma<D>(h) / h * (-5.5) * q * (1.0 + 3.5 * q + 4.0 * q * q) * s4 * s * s * s;
}
} // namespace wendland_c6

/// Gaussian exp(-q^2) truncated at q = 3 and normalised over the truncated
/// ball (so it integrates to 1 exactly, not to 1 - 1e-4).
namespace gaussian {
inline constexpr double support = 3.0;
template <int D = wash::dimensions> double sigma(double h) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2)
    return 1.0 / (PI * h * h * (1.0 - std::exp(-9.0)));
  else
    return 1.0 / (h * h * h * (std::pow(PI, 1.5) * std::erf(3.0) - 6.0 * PI * std::exp(-9.0)));
}
template <int D = wash::dimensions> double W(double r, double h) {
  double q = r / h;
  if (q >= 3.0)
    return 0.0;
  return sigma<D>(h) * std::exp(-q * q);
}
template <int D = wash::dimensions> double dWdr(double r, double h) {
  double q = r / h;
  if (q >= 3.0)
    return 0.0;
  return sigma<D>(h) / h * (-2.0 * q) * std::exp(-q * q);
}
} // namespace gaussian

} // namespace wash::sph
