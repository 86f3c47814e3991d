//===- wash/vec.hpp - fixed-size vectors of the wash API --------*- C++ -*-===//
//
// Vec<T, D> is the position/velocity type of the API. Everything is constexpr so
// that simulations can declare vector constants at namespace scope.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <cmath>
#include <cstddef>
#include <ostream>
#include <type_traits>

namespace wash {

/// @brief A D-dimensional vector with component type T.
/// @tparam T component type (double in the API; float storage is a runtime matter)
/// @tparam D dimension, 2 or 3
template <typename T, int D> class Vec {
  static_assert(D == 2 || D == 3, "wash supports 2D and 3D vectors");

public:
  static constexpr int dimension = D;
  using value_type = T;

  constexpr Vec() : data_{} {}

  /// Component-wise construction: `Vec2D {x, y}`, `Vec2D({x, y})`.
  template <typename... C,
            typename = std::enable_if_t<sizeof...(C) == D && (std::is_arithmetic_v<C> && ...)>>
  constexpr Vec(C... components) : data_{static_cast<T>(components)...} {}

  /// Conversion between component types (float storage <-> double arithmetic).
  template <typename U>
  explicit constexpr Vec(const Vec<U, D> &other) : data_{} {
    for (int i = 0; i < D; ++i)
      data_[i] = static_cast<T>(other.at(i));
  }

  /// Component i by value.
  constexpr T at(int i) const { return data_[i]; }
  /// Pointer to component i, so that `*(v[0]) = 1.0` writes the component.
  constexpr T *operator[](int i) { return &data_[i]; }
  constexpr const T *operator[](int i) const { return &data_[i]; }

  /// Euclidean length, summing squares in component order.
  T magnitude() const { return std::sqrt(dot(*this)); }
  constexpr T dot(const Vec &o) const {
    T s = data_[0] * o.data_[0];
    for (int i = 1; i < D; ++i)
      s += data_[i] * o.data_[i];
    return s;
  }
  /// Component-wise absolute value.
  constexpr Vec abs() const {
    Vec r;
    for (int i = 0; i < D; ++i)
      r.data_[i] = data_[i] < T(0) ? -data_[i] : data_[i];
    return r;
  }

  constexpr Vec &operator+=(const Vec &o) { return apply(o, [](T &a, T b) { a += b; }); }
  constexpr Vec &operator-=(const Vec &o) { return apply(o, [](T &a, T b) { a -= b; }); }
  constexpr Vec &operator*=(T s) { return apply(s, [](T &a, T b) { a *= b; }); }
  constexpr Vec &operator/=(T s) { return apply(s, [](T &a, T b) { a /= b; }); }

  friend constexpr Vec operator+(Vec a, const Vec &b) { return a += b; }
  friend constexpr Vec operator-(Vec a, const Vec &b) { return a -= b; }
  friend constexpr Vec operator*(Vec a, T s) { return a *= s; }
  friend constexpr Vec operator*(T s, Vec a) { return a *= s; }
  friend constexpr Vec operator/(Vec a, T s) { return a /= s; }
  friend constexpr Vec operator-(Vec a) { return a *= T(-1); }
  friend constexpr bool operator==(const Vec &a, const Vec &b) {
    for (int i = 0; i < D; ++i)
      if (a.data_[i] != b.data_[i])
        return false;
    return true;
  }
  friend constexpr bool operator!=(const Vec &a, const Vec &b) { return !(a == b); }

  /// Prints `(x, y)` or `(x, y, z)`.
  friend std::ostream &operator<<(std::ostream &os, const Vec &v) {
    os << '(' << v.data_[0];
    for (int i = 1; i < D; ++i)
      os << ", " << v.data_[i];
    return os << ')';
  }

private:
  template <typename Other, typename Op> constexpr Vec &apply(const Other &o, Op op) {
    for (int i = 0; i < D; ++i) {
      if constexpr (std::is_same_v<Other, Vec>)
        op(data_[i], o.data_[i]);
      else
        op(data_[i], o);
    }
    return *this;
  }

  T data_[D];
};

using Vec2D = Vec<double, 2>;
using Vec3D = Vec<double, 3>;

/// Sign of v: -1, 0 or +1 in v's type.
template <typename T> constexpr T sgn(T v) { return T((T(0) < v) - (v < T(0))); }

} // namespace wash
