// Shape geometry against the closed forms of each solid.

#include "core/ShapeGeometry.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/Angle.h"

namespace tabletop {
namespace {

constexpr double kTol = 1e-12;

TEST(ShapeGeometry, BoxesAndSpheresMatchTheirClosedForms) {
  const ShapeGeometry c = ShapeGeometry::cube(0.2);
  EXPECT_NEAR(c.volume(), 0.008, kTol);
  EXPECT_NEAR(c.inertia(3.0).x, 3.0 * 0.04 / 6.0, kTol);  // m s^2 / 6
  EXPECT_NEAR(c.boundingRadius(), 0.1 * std::sqrt(3.0), kTol);
  const ShapeGeometry b = ShapeGeometry::box(0.1, 0.2, 0.3);
  EXPECT_NEAR(b.inertia(2.0).y, 2.0 * (0.01 + 0.09) / 12.0, kTol);  // m (w^2 + d^2) / 12 about Y
  EXPECT_NEAR(b.below(), 0.1, kTol);
  EXPECT_NEAR(b.smallestHalfDimension(), 0.05, kTol);
  const ShapeGeometry s = ShapeGeometry::sphere(0.05);
  EXPECT_NEAR(s.volume(), 4.0 / 3.0 * kPi * 1.25e-4, kTol);
  EXPECT_NEAR(s.inertia(1.0).z, 0.4 * 0.0025, kTol);
  // A box turned by 45 degrees is bounded by a square of half side
  // (hx + hz) / sqrt(2).
  const auto [fx, fz] = b.topFootprint(45.0);
  EXPECT_NEAR(fx, (0.05 + 0.15) / std::sqrt(2.0), kTol);
  EXPECT_NEAR(fz, fx, kTol);
}

// A cylinder: I_axis = m r^2 / 2, I_transverse = m (3 r^2 + h^2) / 12,
// centroid half way up. A frustum: volume pi h (R^2 + R r + r^2) / 3,
// centroid h (R^2 + 2 R r + 3 r^2) / (4 (R^2 + R r + r^2)) above the base.
TEST(ShapeGeometry, CylindersAndFrustumsMatchTheirClosedForms) {
  const ShapeGeometry c = ShapeGeometry::cylinder(0.05, 0.05, 0.3);
  EXPECT_NEAR(c.inertia(2.0).y, 2.0 * 0.0025 / 2.0, kTol);
  EXPECT_NEAR(c.inertia(2.0).x, 2.0 * (3.0 * 0.0025 + 0.09) / 12.0, kTol);
  EXPECT_NEAR(c.centroidHeight(), 0.15, kTol);
  const double R = 0.08, r = 0.02, h = 0.2;
  const ShapeGeometry f = ShapeGeometry::cylinder(R, r, h);
  EXPECT_NEAR(f.volume(), kPi * h * (R * R + R * r + r * r) / 3.0, kTol);
  EXPECT_NEAR(f.below(), h * (R * R + 2 * R * r + 3 * r * r) / (4 * (R * R + R * r + r * r)), kTol);
  EXPECT_NEAR(f.below() + f.above(), h, kTol);
  EXPECT_NEAR(f.topFootprint(30.0).first, r, kTol);
  EXPECT_EQ(ShapeGeometry::fromSizes(ShapeKind::Cylinder, {R, r, h})->sizes(), (std::vector<double>{R, r, h}));
  EXPECT_FALSE(ShapeGeometry::fromSizes(ShapeKind::Cube, {R, r}).has_value());
}

}  // namespace
}  // namespace tabletop
