#include "core/DirectionDef.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/Arrow.h"

namespace tabletop {
namespace {

// Unit vectors are exact to a few ulps.
constexpr double kTol = 1e-12;

TEST(DirectionDef, NamesRoundTrip) {
  for (auto d : {DirectionDef::Left, DirectionDef::Right, DirectionDef::Front, DirectionDef::Back}) {
    EXPECT_EQ(directionFromString(toString(d)), d);
  }
  EXPECT_FALSE(directionFromString("left").has_value());
  EXPECT_FALSE(directionFromString("Up").has_value());
}

// Report 2: the direction is named after the face pushed. Left pushes the
// entity towards +X, Right towards -X, Front towards -Z, Back towards +Z.
TEST(DirectionDef, PushesAwayFromTheNamedFace) {
  const Vec3 left = pushDirection(directionAngleDegrees(DirectionDef::Left));
  const Vec3 right = pushDirection(directionAngleDegrees(DirectionDef::Right));
  const Vec3 front = pushDirection(directionAngleDegrees(DirectionDef::Front));
  const Vec3 back = pushDirection(directionAngleDegrees(DirectionDef::Back));
  EXPECT_NEAR(left.x, 1.0, kTol);
  EXPECT_NEAR(left.z, 0.0, kTol);
  EXPECT_NEAR(right.x, -1.0, kTol);
  EXPECT_NEAR(right.z, 0.0, kTol);
  EXPECT_NEAR(front.x, 0.0, kTol);
  EXPECT_NEAR(front.z, -1.0, kTol);
  EXPECT_NEAR(back.x, 0.0, kTol);
  EXPECT_NEAR(back.z, 1.0, kTol);
}

// Report 3.8: X' = X + Step cos(Angle), Z' = Z - Step sin(Angle).
TEST(DirectionDef, AngleFollowsReportFormula) {
  for (double a : {0.0, 30.0, 45.0, 123.0, -60.0, 300.0}) {
    const Vec3 d = pushDirection(a);
    const double r = a * 3.14159265358979323846 / 180.0;
    EXPECT_NEAR(d.x, std::cos(r), kTol) << a;
    EXPECT_NEAR(d.y, 0.0, kTol) << a;
    EXPECT_NEAR(d.z, -std::sin(r), kTol) << a;
    EXPECT_NEAR(d.length(), 1.0, kTol) << a;
  }
}

// A face arrow turns with the entity's yaw; an angle arrow does not.
TEST(Arrow, FaceArrowTurnsWithTheEntity) {
  Arrow face{"A", DirectionDef::Front, 0.0};
  EXPECT_DOUBLE_EQ(face.worldAngleDegrees(0.0), 90.0);
  EXPECT_DOUBLE_EQ(face.worldAngleDegrees(30.0), 120.0);
  Arrow angle{"A", std::nullopt, 15.0};
  EXPECT_DOUBLE_EQ(angle.worldAngleDegrees(30.0), 15.0);
}

}  // namespace
}  // namespace tabletop
