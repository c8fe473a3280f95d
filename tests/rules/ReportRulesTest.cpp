// The report's rules, each checked on hand-worked cases at its boundaries.

#include "rules/ReportRules.h"

#include <gtest/gtest.h>

namespace tabletop::rules {
namespace {

// Decimal inputs are exact to a few ulps.
constexpr double kTol = 1e-12;

const TableEdges kTable{-0.6, 0.6, -0.4, 0.4};

// Report 3.8 by hand: a step of 0.2 m at 30 degrees from (0.1, 0.8, 0.1):
// X' = 0.1 + 0.2 * 0.866025 = 0.273205, Z' = 0.1 - 0.2 * 0.5 = 0.0.
TEST(ReportRules, StepTargetFollowsTheAngle) {
  const Vec3 t = stepTarget({0.1, 0.8, 0.1}, 0.2, 30.0);
  EXPECT_NEAR(t.x, 0.2732050807568877, kTol);
  EXPECT_NEAR(t.y, 0.8, kTol);
  EXPECT_NEAR(t.z, 0.0, kTol);
  const Vec3 back = stepTarget({0, 0, 0}, 0.5, 270.0);  // DirectionDef Back: towards +Z
  EXPECT_NEAR(back.x, 0.0, kTol);
  EXPECT_NEAR(back.z, 0.5, kTol);
}

// Report 3.5: aligned when one extent contains the other's; the partial
// overlap of figure 3-7 is not aligned.
TEST(ReportRules, AlignmentIsContainmentOfAnExtent) {
  const Boundary a = cubeBoundary({0, 0, 0}, 0.1);
  EXPECT_TRUE(aligned(a, cubeBoundary({0.3, 0, 0.0}, 0.1)));    // same Z extent
  EXPECT_TRUE(aligned(a, cubeBoundary({0.3, 0, 0.02}, 0.04)));  // small one's Z inside
  EXPECT_TRUE(aligned(a, cubeBoundary({0.3, 0, 0.03}, 0.04)));  // touching the far side: inside
  EXPECT_FALSE(aligned(a, cubeBoundary({0.3, 0, 0.06}, 0.1)));  // figure 3-7
  EXPECT_TRUE(aligned(a, cubeBoundary({0.0, 0, 0.5}, 0.1)));    // same X extent
}

// Report 3.6.1 along X: touching along the force is no collision (strict);
// touching sideways is overlap (inclusive).
TEST(ReportRules, CubesAlongXAtTheirBoundaries) {
  const Vec3 a{0, 0, 0};
  EXPECT_TRUE(cubesCollide(a, 0.1, {0.0999, 0, 0}, 0.1, ForceAxis::X));
  EXPECT_FALSE(cubesCollide(a, 0.1, {0.1, 0, 0}, 0.1, ForceAxis::X));      // faces touch along X
  EXPECT_TRUE(cubesCollide(a, 0.1, {0.05, 0, 0.1}, 0.1, ForceAxis::X));    // sideways faces touch
  EXPECT_FALSE(cubesCollide(a, 0.1, {0.05, 0, 0.1001}, 0.1, ForceAxis::X));
  EXPECT_TRUE(cubesCollide(a, 0.2, {0.1, 0, 0.0}, 0.02, ForceAxis::X));    // small one inside across
  EXPECT_TRUE(cubesCollide(a, 0.02, {0.1, 0, 0.0}, 0.2, ForceAxis::X));    // and the other way round
}

// Along Z, the same with X and Z exchanged.
TEST(ReportRules, CubesAlongZAtTheirBoundaries) {
  const Vec3 a{0, 0, 0};
  EXPECT_TRUE(cubesCollide(a, 0.1, {0, 0, -0.0999}, 0.1, ForceAxis::Z));
  EXPECT_FALSE(cubesCollide(a, 0.1, {0, 0, -0.1}, 0.1, ForceAxis::Z));
  EXPECT_TRUE(cubesCollide(a, 0.1, {0.1, 0, 0.05}, 0.1, ForceAxis::Z));
  EXPECT_FALSE(cubesCollide(a, 0.1, {0.1001, 0, 0.05}, 0.1, ForceAxis::Z));
}

// Where the printed Z formula's typos change the answer: cubes of 0.1 m
// 0.15 m apart along Z are clear of each other (|dZ| = 0.15 >= 0.1), but
// SideLength1 + SideLength2 = 0.2 calls it a collision.
TEST(ReportRules, PrintedZFormulaDiffersWhereItsTyposBite) {
  const Vec3 a{0, 0, 0}, b{0.1, 0, 0.15};
  EXPECT_FALSE(cubesCollide(a, 0.1, b, 0.1, ForceAxis::Z));
  EXPECT_TRUE(cubesCollideAsPrintedAlongZ(a, 0.1, b, 0.1));
  // And where both agree: a plain overlap.
  EXPECT_TRUE(cubesCollide(a, 0.1, {0.1, 0, 0.05}, 0.1, ForceAxis::Z));
  EXPECT_TRUE(cubesCollideAsPrintedAlongZ(a, 0.1, {0.1, 0, 0.05}, 0.1));
}

// Report 3.6.2: touching spheres collide (<=).
TEST(ReportRules, SpheresCollideWhenTouching) {
  EXPECT_TRUE(spheresCollide({0, 0, 0}, 0.03, {0.08, 0, 0}, 0.05));
  EXPECT_TRUE(spheresCollide({0, 0, 0}, 0.03, {0.06, 0, 0.05}, 0.05));  // 0.0781 < 0.08
  EXPECT_FALSE(spheresCollide({0, 0, 0}, 0.03, {0.06, 0, 0.06}, 0.05)); // 0.0849 > 0.08
}

// Report 3.7 with the erratum: the step's X and Z components each.
TEST(ReportRules, SphereStaysOnTableUsesStepComponents) {
  // 0.2 m at 45 degrees from (0.45, 0, 0): X' = 0.5914, Z' = -0.1414, stays.
  EXPECT_TRUE(sphereStaysOnTable({0.45, 0, 0}, 0.2, 45.0, kTable));
  // The printed itsStep for both would put X' at 0.65: off the table.
  EXPECT_GT(0.45 + 0.2, kTable.xRight);
  EXPECT_FALSE(sphereStaysOnTable({0.45, 0, 0}, 0.2, 0.0, kTable));
  // Exactly on the edge (binary-exact numbers: 0.5 + 0.125 = 0.625).
  const TableEdges exact{-0.625, 0.625, -0.375, 0.375};
  EXPECT_TRUE(sphereStaysOnTable({0.5, 0, 0}, 0.125, 0.0, exact));
  EXPECT_FALSE(sphereStaysOnTable({0.5, 0, 0}, 0.125 + 1e-12, 0.0, exact));
}

}  // namespace
}  // namespace tabletop::rules
