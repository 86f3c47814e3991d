// Every kernel integrates to 1 over its support, in 2D and 3D, and its dW/dr
// is the derivative of W (central finite differences).
#include <wash/sph/kernels.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace sph = wash::sph;

namespace {

using Radial = std::function<double(double r, double h)>;

struct Kernel {
  const char *name;
  double support;
  Radial W2, W3, dW2, dW3;
};

#define WASH_KERNEL(ns)                                                                            \
  Kernel { #ns, sph::ns::support, sph::ns::W<2>, sph::ns::W<3>, sph::ns::dWdr<2>, sph::ns::dWdr<3> }

const Kernel kernels[] = {WASH_KERNEL(cubic_spline), WASH_KERNEL(quintic_spline),
                          WASH_KERNEL(wendland_c2),  WASH_KERNEL(wendland_c4),
                          WASH_KERNEL(wendland_c6),  WASH_KERNEL(gaussian)};

/// The integral of W over the D-ball of radius support * h, as the radial
/// integral of (surface of the sphere of radius r) W(r), by composite
/// Simpson's rule. The panel count is a multiple of 6, so every break of the
/// piecewise kernels (q = 1, 2) falls on a panel's edge.
double integral(const Radial &W, int dimension, double support, double h) {
  const int panels = 6000;
  const double R = support * h, step = R / panels;
  auto f = [&](double r) {
    double surface = dimension == 2 ? 2.0 * PI * r : 4.0 * PI * r * r;
    return surface * W(r, h);
  };
  double sum = 0.0;
  for (int k = 0; k < panels; k++) {
    double a = k * step, b = a + step;
    // The Gaussian's cut at q = 3 is a jump: evaluate just inside it.
    double fb = k + 1 == panels ? f(std::nextafter(b, 0.0)) : f(b);
    sum += step / 6.0 * (f(a) + 4.0 * f(0.5 * (a + b)) + fb);
  }
  return sum;
}

TEST(Kernels, IntegrateToOneIn2DAnd3D) {
  for (const Kernel &k : kernels)
    for (double h : {0.3, 1.0, 1.7}) {
      EXPECT_NEAR(integral(k.W2, 2, k.support, h), 1.0, 1e-6) << k.name << " 2D h=" << h;
      EXPECT_NEAR(integral(k.W3, 3, k.support, h), 1.0, 1e-6) << k.name << " 3D h=" << h;
    }
}

TEST(Kernels, GradientIsTheFiniteDifferenceDerivative) {
  const double h = 0.8;
  for (const Kernel &k : kernels)
    for (int i = 1; i < 60; i++) {
      const double r = k.support * h * i / 60.0, e = 1e-6 * h;
      // Stay off the breaks of the piecewise kernels, where W has no
      // third derivative and the difference quotient loses digits.
      if (std::abs(r / h - std::round(r / h)) < 1e-3)
        continue;
      for (auto [W, dW, dim] : {std::tuple{&k.W2, &k.dW2, 2}, std::tuple{&k.W3, &k.dW3, 3}}) {
        double fd = ((*W)(r + e, h) - (*W)(r - e, h)) / (2.0 * e);
        double scale = std::abs((*W)(0.0, h)) / h;
        EXPECT_NEAR((*dW)(r, h), fd, 1e-7 * scale) << k.name << " " << dim << "D r=" << r;
      }
    }
}

TEST(Kernels, VanishOutsideTheSupportAndPeakAtZero) {
  for (const Kernel &k : kernels) {
    EXPECT_EQ(k.W2(k.support * 0.5, 0.5), 0.0) << k.name;
    EXPECT_EQ(k.W3(k.support * 0.5 * 1.01, 0.5), 0.0) << k.name;
    EXPECT_EQ(k.dW3(k.support * 2.0, 0.5), 0.0) << k.name;
    EXPECT_GT(k.W2(0.0, 0.5), k.W2(0.1, 0.5)) << k.name;
    EXPECT_EQ(k.dW2(0.0, 0.5), 0.0) << k.name;
  }
}

// grad_i W(|x_i - x_j|) = d dW/dr / r, against finite differences in x_i.
TEST(Kernels, VectorGradientIn2DAnd3D) {
  const double h = 0.5, e = 1e-6;
  wash::Vec3D d3{0.21, -0.13, 0.3};
  wash::Vec3D g3 = sph::gradient(d3, d3.magnitude(), sph::wendland_c4::dWdr<3>(d3.magnitude(), h));
  for (int a = 0; a < 3; a++) {
    wash::Vec3D plus = d3, minus = d3;
    *plus[a] += e;
    *minus[a] -= e;
    double fd = (sph::wendland_c4::W<3>(plus.magnitude(), h) -
                 sph::wendland_c4::W<3>(minus.magnitude(), h)) /
                (2.0 * e);
    EXPECT_NEAR(g3.at(a), fd, 1e-6) << a;
  }
  wash::Vec2D d2{-0.4, 0.25};
  wash::Vec2D g2 = sph::gradient(d2, d2.magnitude(), sph::cubic_spline::dWdr<2>(d2.magnitude(), h));
  for (int a = 0; a < 2; a++) {
    wash::Vec2D plus = d2, minus = d2;
    *plus[a] += e;
    *minus[a] -= e;
    double fd = (sph::cubic_spline::W<2>(plus.magnitude(), h) -
                 sph::cubic_spline::W<2>(minus.magnitude(), h)) /
                (2.0 * e);
    EXPECT_NEAR(g2.at(a), fd, 1e-6) << a;
  }
}

} // namespace
