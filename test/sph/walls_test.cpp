// Adami walls: a wall particle under hydrostatic fluid gets the hydrostatic
// pressure at its own depth, and the no-slip velocity mirrors the fluid's.
#include <wash/sph/kernels.hpp>
#include <wash/sph/walls.hpp>

#include <gtest/gtest.h>

namespace sph = wash::sph;

TEST(AdamiWall, ExtrapolatesTheHydrostaticPressureToTheWall) {
  const double rho = 1000.0, g = 9.81, surface = 1.0, dx = 0.02, h = 1.3 * dx;
  const wash::Vec2D wall{0.5, -0.01}; // below the fluid, which fills y >= 0
  sph::AdamiWall<2> sums;
  for (int j = 0; j < 5; j++)
    for (int i = -5; i <= 5; i++) {
      wash::Vec2D x{0.5 + i * dx, (j + 0.5) * dx};
      wash::Vec2D d = wall - x;
      double W = sph::wendland_c2::W<2>(d.magnitude(), h);
      if (W > 0.0)
        sums.add(W, rho * g * (surface - x.at(1)), rho, d, wash::Vec2D{0.3, 0.1});
    }
  ASSERT_FALSE(sums.empty());
  EXPECT_NEAR(sums.pressure(wash::Vec2D{0.0, -g}), rho * g * (surface - wall.at(1)),
              1e-9 * rho * g);
  // A wall accelerating upwards pushes harder on the fluid above it.
  EXPECT_GT(sums.pressure(wash::Vec2D{0.0, -g}, wash::Vec2D{0.0, g}),
            sums.pressure(wash::Vec2D{0.0, -g}) + 0.005 * rho * g);
  wash::Vec2D v = sums.velocity();
  EXPECT_NEAR(v.at(0), -0.3, 1e-12);
  EXPECT_NEAR(v.at(1), -0.1, 1e-12);
}

TEST(AdamiWall, WithoutFluidNeighboursTheWallIsAtRest) {
  sph::AdamiWall<3> none;
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.pressure(wash::Vec3D{0.0, -9.81, 0.0}), 0.0);
  EXPECT_EQ(none.velocity(wash::Vec3D{1.0, 0.0, 0.0}), (wash::Vec3D{1.0, 0.0, 0.0}));
}
