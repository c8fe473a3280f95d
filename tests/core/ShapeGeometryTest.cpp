// Shape geometry against the closed forms of each solid.

#include "core/ShapeGeometry.h"

#include <algorithm>
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

// A solid cone of base radius R and height h (point up): volume pi R^2 h / 3,
// centroid h / 4 above the base, I_axis = 3 m R^2 / 10, I_transverse about
// the centroid = 3 m R^2 / 20 + 3 m h^2 / 80. Point down (base radius 0),
// the same solid upside down: its centroid 3 h / 4 above the point.
TEST(ShapeGeometry, ConesMatchTheirClosedForms) {
  for (const double R : {0.01, 0.05, 0.3}) {
    for (const double h : {0.02, 0.1, 0.8}) {
      for (const double m : {0.1, 2.0}) {
        const ShapeGeometry up = ShapeGeometry::cylinder(R, 0.0, h);
        const ShapeGeometry down = ShapeGeometry::cylinder(0.0, R, h);
        for (const ShapeGeometry& c : {up, down}) {
          const double scale = R * R * h;  // the cone's size, for relative tolerances
          EXPECT_NEAR(c.volume(), kPi * R * R * h / 3.0, kTol * scale);
          EXPECT_NEAR(c.inertia(m).y, 0.3 * m * R * R, kTol * m * R * R);
          EXPECT_NEAR(c.inertia(m).x, 3.0 * m * R * R / 20.0 + 3.0 * m * h * h / 80.0, kTol * m * (R * R + h * h));
          EXPECT_NEAR(c.inertia(m).z, c.inertia(m).x, kTol * m * (R * R + h * h));
          EXPECT_NEAR(c.smallestHalfDimension(), std::min(R, 0.5 * h), kTol);
        }
        EXPECT_NEAR(up.centroidHeight(), h / 4.0, kTol * h);
        EXPECT_NEAR(down.centroidHeight(), 3.0 * h / 4.0, kTol * h);
        EXPECT_NEAR(up.topFootprint(0.0).first, 0.0, kTol);  // nothing rests on a point
        EXPECT_NEAR(up.halfExtents().x, R, kTol);
      }
    }
  }
}

}  // namespace
}  // namespace tabletop
