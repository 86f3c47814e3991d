#include <wash/vec.hpp>

#include <gtest/gtest.h>

#include <sstream>

using wash::Vec2D;
using wash::Vec3D;

// The seed declares vector constants at namespace scope.
constexpr Vec2D constant{3.35, 0.51};
static_assert(constant.at(0) == 3.35 && constant.at(1) == 0.51);
static_assert((constant * 2.0).at(1) == 1.02);

TEST(Vec, BracedListConstructionAndAccess) {
  Vec2D v = Vec2D({1.5, -2.0});
  EXPECT_EQ(v.at(0), 1.5);
  EXPECT_EQ(v.at(1), -2.0);
  Vec3D zero;
  EXPECT_EQ(zero, Vec3D(0.0, 0.0, 0.0));
}

TEST(Vec, IndexOperatorGivesAWritablePointer) {
  Vec2D v{1.0, 2.0};
  *(v[0]) = 7.0;
  *(v[1]) *= -1;
  EXPECT_EQ(v, Vec2D(7.0, -2.0));
  const Vec2D c{4.0, 5.0};
  EXPECT_EQ(*(c[1]), 5.0);
}

TEST(Vec, ArithmeticIsComponentWise) {
  Vec3D a{1.0, 2.0, 3.0}, b{0.5, -1.0, 2.0};
  EXPECT_EQ(a + b, Vec3D(1.5, 1.0, 5.0));
  EXPECT_EQ(a - b, Vec3D(0.5, 3.0, 1.0));
  EXPECT_EQ(a * 2.0, Vec3D(2.0, 4.0, 6.0));
  EXPECT_EQ(2.0 * a, a * 2.0);
  EXPECT_EQ(a / 2.0, Vec3D(0.5, 1.0, 1.5));
  EXPECT_EQ(-a, Vec3D(-1.0, -2.0, -3.0));
  Vec3D c = a;
  c += b;
  c -= a;
  EXPECT_EQ(c, b);
  c *= 4.0;
  c /= 2.0;
  EXPECT_EQ(c, b * 2.0);
}

TEST(Vec, MagnitudeIsEuclideanAndAbsComponentWise) {
  EXPECT_EQ((Vec2D{3.0, -4.0}).magnitude(), 5.0);
  EXPECT_EQ((Vec3D{2.0, 3.0, 6.0}).magnitude(), 7.0);
  EXPECT_EQ((Vec2D{-1.5, 2.0}).abs(), Vec2D(1.5, 2.0));
  EXPECT_EQ((Vec2D{1.0, 2.0}).dot(Vec2D{3.0, 4.0}), 11.0);
}

TEST(Vec, SignFunction) {
  EXPECT_EQ(wash::sgn(-2.5), -1.0);
  EXPECT_EQ(wash::sgn(0.0), 0.0);
  EXPECT_EQ(wash::sgn(3.0), 1.0);
}

TEST(Vec, PrintsAsATuple) {
  std::ostringstream os;
  os << Vec2D{1.5, -2.0} << ' ' << Vec3D{1.0, 2.0, 3.0};
  EXPECT_EQ(os.str(), "(1.5, -2) (1, 2, 3)");
}
