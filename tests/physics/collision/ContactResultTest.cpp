// ContactResult: the radius within which a new contact point replaces a
// kept one, and what it keeps for a small body.

#include "physics/collision/ContactResult.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "physics/shapes/Cube.h"
#include "physics/shapes/Seating.h"
#include "physics/shapes/Sphere.h"
#include "support/PhysicsFixture.h"

namespace tabletop {
namespace {

using test::PhysicsFixture;

constexpr double kThreshold = 0.02;  // Bullet's contact breaking threshold, m

// Half the smallest extent of the smaller shape, never above the breaking
// threshold: closed forms, to rounding.
TEST(ContactResult, MergeRadiusIsHalfTheSmallestExtent) {
  const btBoxShape grain(btVector3(0.0025, 0.0025, 0.0025));
  const btBoxShape plank(btVector3(0.5, 0.01, 0.2));
  const btBoxShape block(btVector3(0.2, 0.2, 0.2));
  const btSphereShape ball(0.015);
  const btStaticPlaneShape floor(btVector3(0, 1, 0), 0);
  EXPECT_NEAR(ContactResult::mergeRadius(grain, floor, kThreshold), 0.0025, 1e-12);
  EXPECT_NEAR(ContactResult::mergeRadius(floor, grain, kThreshold), 0.0025, 1e-12);
  EXPECT_NEAR(ContactResult::mergeRadius(plank, block, kThreshold), 0.01, 1e-12);
  EXPECT_NEAR(ContactResult::mergeRadius(ball, block, kThreshold), 0.015, 1e-12);
  EXPECT_DOUBLE_EQ(ContactResult::mergeRadius(block, floor, kThreshold), kThreshold);
}

// A 5 mm cube resting on the floor keeps a point at each of its four lower
// corners (to 1% of its size), not one point for all four, and rests at its
// height to 1% of its size.
TEST_F(PhysicsFixture, SmallCubeKeepsAPointAtEachCorner) {
  World& w = makeTable();
  constexpr double kSize = 0.005;
  const Shape& grain = w.addEntity(std::make_unique<Cube>("grain", kSize), 1.25e-4, Material{},
                                   btVector3(2.0, seated(kSize / 2), 0), 0);
  simulate(1.0);
  const std::vector<Vec3> points = w.contactPoints();
  ASSERT_EQ(points.size(), 4u);
  const btVector3 centre = grain.position();
  std::set<std::pair<bool, bool>> corners;
  for (const Vec3& p : points) {
    EXPECT_NEAR(std::abs(p.x - centre.x()), kSize / 2, 0.01 * kSize);
    EXPECT_NEAR(std::abs(p.z - centre.z()), kSize / 2, 0.01 * kSize);
    corners.insert({p.x > centre.x(), p.z > centre.z()});
  }
  EXPECT_EQ(corners.size(), 4u) << "one point per corner";
  EXPECT_NEAR(grain.position().y(), kSize / 2, 0.01 * kSize);
}

}  // namespace
}  // namespace tabletop
