// A round solid's ends are its nominal ones: a cylinder's rims, and a
// cone's or truncated cone's rings and point as its size gives them,
// though its hull draws them in by its margin (Cylinder.cpp). Over cones
// point up and point down, truncated cones both ways and cylinders; none
// for a box or a ball.

#include <cmath>
#include <optional>

#include <gtest/gtest.h>

#include "core/ShapeGeometry.h"
#include "physics/shapes/Cube.h"
#include "physics/shapes/Cylinder.h"
#include "physics/shapes/RoundEnds.h"
#include "physics/shapes/Sphere.h"

namespace tabletop {
namespace {

constexpr double kTolerance = 1e-12;  // m

TEST(RoundEnds, AreTheNominalRimsAndPointOfEveryRoundSolid) {
  const double sizes[][3] = {{0.05, 0.05, 0.1}, {0.08, 0.08, 0.03}, {0.05, 0.0, 0.1}, {0.0, 0.03, 0.12},
                             {0.05, 0.03, 0.1}, {0.02, 0.06, 0.05}};
  for (const auto& size : sizes) {
    const double base = size[0], top = size[1], height = size[2];
    const Cylinder body("C", base, top, height);
    const std::optional<RoundEnds> ends = roundEnds(body.collisionShape());
    ASSERT_TRUE(ends) << base << " " << top << " " << height;
    // The shape's origin is its centroid, the base that far below it.
    const double below = ShapeGeometry::cylinder(base, top, height).centroidHeight();
    EXPECT_NEAR(ends->y[0], -below, kTolerance) << base << " " << top << " " << height;
    EXPECT_NEAR(ends->y[1], height - below, kTolerance) << base << " " << top << " " << height;
    EXPECT_NEAR(ends->radius[0], base, kTolerance) << base << " " << top << " " << height;
    EXPECT_NEAR(ends->radius[1], top, kTolerance) << base << " " << top << " " << height;
  }
}

TEST(RoundEnds, NoneForABoxOrABall) {
  EXPECT_FALSE(roundEnds(Cube("B", 0.1).collisionShape()));
  EXPECT_FALSE(roundEnds(Sphere("S", 0.05).collisionShape()));
}

}  // namespace
}  // namespace tabletop
