// PointBoxes: the box a contact point lies on, on either side (a box, or a
// compound's box child such as the table top), found once a part and found
// again once the point has moved.

#include "physics/step/FaceExits.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(PointBoxes, FindsEachSidesBoxAndLooksAgainWhenAPointMoves) {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher(&configuration);
  // A table: its top a 1.2 x 0.04 x 0.8 m box child at 0.73 m, and a leg.
  btBoxShape top(btVector3(0.6, 0.02, 0.4));
  btCylinderShape leg(btVector3(0.02, 0.35, 0.02));
  btCompoundShape compound;
  btTransform place;
  place.setIdentity();
  place.setOrigin(btVector3(0, 0.73, 0));
  compound.addChildShape(place, &top);
  place.setOrigin(btVector3(0.5, 0.35, 0.3));
  compound.addChildShape(place, &leg);
  btCollisionObject table;
  table.setCollisionShape(&compound);
  // A 0.1 m cube resting on it, turned 30 degrees about the vertical.
  btBoxShape cubeShape(btVector3(0.05, 0.05, 0.05));
  btCollisionObject cube;
  cube.setCollisionShape(&cubeShape);
  btTransform cubePlace(btQuaternion(btVector3(0, 1, 0), SIMD_PI / 6), btVector3(0.1, 0.80, -0.2));
  cube.setWorldTransform(cubePlace);

  btPersistentManifold* manifold = dispatcher.getNewManifold(&cube, &table);
  const btVector3 corner = cubePlace * btVector3(0.05, -0.05, 0.05);
  btManifoldPoint point(cubePlace.invXform(corner), corner, btVector3(0, 1, 0), 0);
  point.m_positionWorldOnA = corner;
  point.m_positionWorldOnB = corner;
  manifold->addManifoldPoint(point);

  PointBoxes boxes;
  boxes.start(dispatcher);
  const std::optional<PointBoxes::Box>& onTable = boxes.at(*manifold, 0, 0, 1);
  ASSERT_TRUE(onTable.has_value());
  EXPECT_EQ(onTable->half, top.getHalfExtentsWithMargin());
  EXPECT_EQ(onTable->place.getOrigin(), btVector3(0, 0.73, 0));
  const std::optional<PointBoxes::Box>& onCube = boxes.at(*manifold, 0, 0, 0);
  ASSERT_TRUE(onCube.has_value());
  EXPECT_EQ(onCube->half, cubeShape.getHalfExtentsWithMargin());
  EXPECT_EQ(onCube->place.getOrigin(), cubePlace.getOrigin());

  // Moved off the table top, onto the leg (a cylinder, not a box): no box.
  manifold->getContactPoint(0).m_positionWorldOnB = btVector3(0.5, 0.35, 0.3);
  EXPECT_FALSE(boxes.at(*manifold, 0, 0, 1).has_value());
  // Back on the top, and a new part: found again.
  manifold->getContactPoint(0).m_positionWorldOnB = corner;
  boxes.start(dispatcher);
  EXPECT_TRUE(boxes.at(*manifold, 0, 0, 1).has_value());
  dispatcher.releaseManifold(manifold);
}

}  // namespace
}  // namespace tabletop
