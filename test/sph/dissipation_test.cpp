// The pair terms of the dissipation switches, against their formulas and
// their signs.
#include <wash/sph/dissipation.hpp>
#include <wash/sph/time_step.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace sph = wash::sph;

TEST(Dissipation, MonaghanViscosity) {
  const double h = 0.1, r = 0.05, vr = -0.2;
  double mu = sph::monaghan_mu(h, vr, r);
  EXPECT_DOUBLE_EQ(mu, h * vr / (r * r + 0.01 * h * h));
  double pi = sph::monaghan_viscosity(1.0, 2.0, 1.0, 3.0, mu, 2.0);
  EXPECT_DOUBLE_EQ(pi, (-1.0 * 2.0 * mu + 2.0 * mu * mu) / 2.0);
  EXPECT_GT(pi, 0.0); // approaching pairs are pushed apart
  EXPECT_DOUBLE_EQ(sph::monaghan_viscosity(1.0, 2.0, 1.0, 3.0, mu, 2.0, 0.25), 0.25 * pi);
}

TEST(Dissipation, BalsaraSwitchIsOneInCompressionAndSmallInShear) {
  EXPECT_NEAR(sph::balsara_switch(-5.0, 0.0, 1.0, 0.1), 5.0 / (5.0 + 1e-3), 1e-15);
  EXPECT_LT(sph::balsara_switch(0.01, 5.0, 1.0, 0.1), 0.01);
  EXPECT_EQ(sph::balsara_switch(0.0, 0.0, 1.0, 0.1), 0.0);
}

TEST(Dissipation, CrossProductIn2DAnd3D) {
  wash::Vec3D c = sph::cross(wash::Vec3D{1.0, 0.0, 0.0}, wash::Vec3D{0.0, 1.0, 0.0});
  EXPECT_EQ(c, (wash::Vec3D{0.0, 0.0, 1.0}));
  EXPECT_EQ(sph::cross(wash::Vec2D{2.0, 0.0}, wash::Vec2D{0.0, 3.0}), 6.0);
}

TEST(Dissipation, SignalVelocity) {
  EXPECT_EQ(sph::signal_velocity(1.0, 2.0, 0.5, 0.1), 3.0);
  EXPECT_DOUBLE_EQ(sph::signal_velocity(1.0, 2.0, -0.1, 0.1), 6.0);
}

TEST(Dissipation, ConductivityFlowsFromHotToCold) {
  const double dW = -3.0; // dW/dr < 0
  double hot = sph::price_conductivity(1.0, 1.0, 2.0, 1.0, 2.0, 1.0, 1.0, dW);
  double cold = sph::price_conductivity(1.0, 1.0, 1.0, 2.0, 1.0, 2.0, 1.0, dW);
  EXPECT_LT(hot, 0.0);
  EXPECT_EQ(hot, -cold);
  EXPECT_EQ(sph::price_conductivity(1.0, 1.0, 1.0, 1.0, 2.0, 1.0, 1.0, dW), 0.0);
}

TEST(Dissipation, DeltaSphDiffusesDensity) {
  const double dW = -2.0, r = 0.1;
  double up = sph::delta_sph_diffusion(0.1, 0.05, 40.0, 1000.0, 1010.0, 1.0, r, dW);
  EXPECT_GT(up, 0.0); // the lighter particle gains density
  EXPECT_DOUBLE_EQ(up, 2.0 * 0.1 * 0.05 * 40.0 * 10.0 * (2.0 / r) * 1.0 / 1010.0);
  EXPECT_EQ(sph::delta_sph_diffusion(0.1, 0.05, 40.0, 1000.0, 1000.0, 1.0, r, dW), 0.0);
}

TEST(Dissipation, XsphPullsTowardsTheNeighboursVelocity) {
  wash::Vec2D c = sph::xsph_correction(0.5, 2.0, 1.0, 3.0, wash::Vec2D{1.0, -1.0}, 0.25);
  EXPECT_DOUBLE_EQ(c.at(0), 0.5 * 2.0 / 2.0 * 0.25);
  EXPECT_DOUBLE_EQ(c.at(1), -0.5 * 2.0 / 2.0 * 0.25);
}

TEST(TimeStep, Criteria) {
  EXPECT_DOUBLE_EQ(sph::courant_time_step(0.25, 0.1, 50.0), 0.25 * 0.1 / 50.0);
  EXPECT_DOUBLE_EQ(sph::force_time_step(0.25, 0.1, 9.81), 0.25 * std::sqrt(0.1 / 9.81));
  EXPECT_TRUE(std::isinf(sph::force_time_step(0.25, 0.1, 0.0)));
  EXPECT_DOUBLE_EQ(sph::viscous_time_step(0.125, 0.1, 1e-3), 0.125 * 0.01 / 1e-3);
  EXPECT_TRUE(std::isinf(sph::viscous_time_step(0.125, 0.1, 0.0)));
}
