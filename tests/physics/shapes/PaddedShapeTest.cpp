// PaddedShape: the table's children reach Bullet's contact breaking
// threshold beyond themselves, so a body resting on the top keeps its
// contact through a rounding-sized lift.

#include "physics/shapes/PaddedShape.h"

#include <gtest/gtest.h>

#include "physics/shapes/Cube.h"
#include "physics/shapes/Seating.h"
#include "support/PhysicsFixture.h"

namespace tabletop {
namespace {

using test::kG;
using test::PhysicsFixture;

// The bounding box is the shape's, grown by the pad on every side (to
// rounding); the shape stays a box to Bullet's dispatcher.
TEST(PaddedShape, BoundingBoxReachesThePadBeyondTheShape) {
  constexpr double kPad = 0.02;
  const btBoxShape plain(btVector3(0.6, 0.02, 0.4));
  const PaddedShape<btBoxShape> padded(kPad, btVector3(0.6, 0.02, 0.4));
  btTransform pose(btQuaternion(btVector3(0, 1, 0), 0.3), btVector3(1, 2, 3));
  btVector3 lo, hi, paddedLo, paddedHi;
  plain.getAabb(pose, lo, hi);
  padded.getAabb(pose, paddedLo, paddedHi);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(paddedLo[axis], lo[axis] - kPad, 1e-12);
    EXPECT_NEAR(paddedHi[axis], hi[axis] + kPad, 1e-12);
  }
  EXPECT_EQ(padded.getShapeType(), BOX_SHAPE_PROXYTYPE);
}

// A cube at rest on the top, lifted to 1 nm above it (its box and the
// top's then no longer overlap), keeps its contact: after the next step it moves
// slower than 1% of the g dt = 4.1 cm/s it gains in one step of free fall,
// the speed Bullet's exact boxes gave it when the top's child algorithm,
// manifold and impulses were dropped.
TEST_F(PhysicsFixture, CubeLiftedByANanometreKeepsItsTableContact) {
  World& w = makeTable();
  const TableSpec& spec = w.table().spec();
  const double top = w.table().topHeight();
  Shape& cube = w.addEntity(std::make_unique<Cube>("A", 0.1), 0.5, Material{},
                            btVector3(spec.centreX, seated(top + 0.05), spec.centreZ), 0);
  simulate(0.5);
  btTransform pose = cube.body()->getWorldTransform();
  pose.getOrigin().setY(top + 0.05 + 1e-9);
  cube.body()->setWorldTransform(pose);
  w.step();
  const double dt = w.settings().timestep;
  EXPECT_LT(cube.body()->getLinearVelocity().length(), 0.01 * kG * dt);
}

}  // namespace
}  // namespace tabletop
