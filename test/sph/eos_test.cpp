// The equations of state round-trip (density -> pressure -> density), and
// their sound speeds are sqrt(dP/drho).
#include <wash/sph/eos.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace sph = wash::sph;

TEST(Eos, TaitRoundTrip) {
  const sph::Tait water{1000.0, 44.3};
  EXPECT_DOUBLE_EQ(water.stiffness(), 44.3 * 44.3 * 1000.0 / 7.0);
  EXPECT_EQ(water.pressure(1000.0), 0.0);
  EXPECT_DOUBLE_EQ(water.sound_speed(1000.0), 44.3);
  for (double rho : {950.0, 990.0, 1000.0, 1003.7, 1050.0}) {
    EXPECT_NEAR(water.density(water.pressure(rho)), rho, 1e-12 * rho) << rho;
    const double e = 1e-4;
    double slope = (water.pressure(rho + e) - water.pressure(rho - e)) / (2.0 * e);
    EXPECT_NEAR(water.sound_speed(rho), std::sqrt(slope), 1e-6 * 44.3) << rho;
  }
  for (double P : {-1e4, 0.0, 19620.0, 1e6})
    EXPECT_NEAR(water.pressure(water.density(P)), P, 1e-9 * water.stiffness()) << P;
}

TEST(Eos, IdealGasRoundTrip) {
  const double gamma = 5.0 / 3.0;
  for (double rho : {0.125, 1.0, 64.0})
    for (double u : {1e-8, 0.9, 250.0}) {
      double P = sph::ideal_gas_pressure(gamma, rho, u);
      EXPECT_DOUBLE_EQ(P, (gamma - 1.0) * rho * u);
      EXPECT_NEAR(sph::ideal_gas_energy(gamma, P, rho), u, 1e-15 * u);
      EXPECT_NEAR(sph::ideal_gas_sound_speed(gamma, P, rho),
                  sph::ideal_gas_sound_speed_from_energy(gamma, u), 1e-14 * std::sqrt(u));
      // c^2 = dP/drho at constant entropy: P ~ rho^gamma.
      const double e = 1e-6 * rho;
      double slope =
          P * (std::pow((rho + e) / rho, gamma) - std::pow((rho - e) / rho, gamma)) / (2.0 * e);
      EXPECT_NEAR(sph::ideal_gas_sound_speed(gamma, P, rho), std::sqrt(slope),
                  1e-6 * std::sqrt(slope));
    }
}

TEST(Eos, LinearRoundTripWithBackgroundPressure) {
  const sph::LinearEos eos{1.0, 10.0, 5.0};
  EXPECT_EQ(eos.pressure(1.0), 5.0);
  EXPECT_DOUBLE_EQ(eos.pressure(1.01), 100.0 * 0.01 + 5.0);
  for (double rho : {0.9, 1.0, 1.2})
    EXPECT_NEAR(eos.density(eos.pressure(rho)), rho, 1e-14);
  EXPECT_EQ(eos.sound_speed(1.3), 10.0);
}
