//===- wash/sph/walls.hpp - fixed wall particles (Adami 2012) ---*- C++ -*-===//
//
// Adami, Hu & Adams (2012): a wall particle w takes the pressure and velocity
// the fluid around it extrapolates to it, so that a fluid particle sees a wall
// neighbour as fluid that pushes back:
//   P_w = (sum_f P_f W_wf + (g - a_w) . sum_f rho_f (x_w - x_f) W_wf) / sum_f W_wf
//   v~_w = 2 v_w - sum_f v_f W_wf / sum_f W_wf      (no slip, for viscous terms)
// and its density from the equation of state's inverse. A force kernel on the
// wall particles sums over their fluid neighbours with add(), then asks for
// pressure() and velocity(). Formulas and references: docs/sph-library.md.
//
//===----------------------------------------------------------------------===//
#pragma once

#include <wash/wash.hpp>

namespace wash::sph {

template <int D = wash::dimensions> struct AdamiWall {
  using V = Vec<double, D>;
  double weight = 0.0; ///< sum_f W_wf
  double pressure_sum = 0.0;
  V density_moment{}; ///< sum_f rho_f (x_w - x_f) W_wf
  V velocity_sum{};   ///< sum_f v_f W_wf

  /// One fluid neighbour f at d = x_w - x_f with kernel value W.
  void add(double W, double pressure, double density, const V &d, const V &vel) {
    weight += W;
    pressure_sum += pressure * W;
    density_moment += d * (density * W);
    velocity_sum += vel * W;
  }
  bool empty() const { return weight <= 0.0; }
  /// The wall's pressure, for gravity g and the wall's own acceleration aw.
  double pressure(const V &g, const V &aw = V{}) const {
    return empty() ? 0.0 : (pressure_sum + (g - aw).dot(density_moment)) / weight;
  }
  /// The no-slip velocity v~_w of a wall moving at vw.
  V velocity(const V &vw = V{}) const { return empty() ? vw : vw * 2.0 - velocity_sum / weight; }
};

} // namespace wash::sph
