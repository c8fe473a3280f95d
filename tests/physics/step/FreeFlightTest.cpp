// FreeFlight (src/physics/FreeFlight.cpp): a body touching nothing turns
// exactly, keeps its rotational energy while it falls, and its centre still
// falls as gravity says; a body resting on the table keeps Bullet's
// treatment; every body keeps its gyroscopic flags across steps.

#include "physics/step/FreeFlight.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "physics/shapes/SolidBox.h"
#include "support/PhysicsFixture.h"

namespace tabletop {
namespace {

using FreeFlightTest = test::PhysicsFixture;

// Rotational kinetic energy w.I w / 2 in the body's axes, J.
double spinEnergy(const btRigidBody& body) {
  const btVector3 w = body.getWorldTransform().getBasis().transpose() * body.getAngularVelocity();
  const btVector3 inverse = body.getInvInertiaDiagLocal();
  return 0.5 * (w.x() * w.x() / inverse.x() + w.y() * w.y() / inverse.y() + w.z() * w.z() / inverse.z());
}

// A 0.3 x 0.2 x 0.1 m box released 1 m above the table top, spinning about
// a skew axis at 60 Hz: for 0.3 s it touches nothing. Its rotational
// energy stays to 1e-12 of itself (Bullet's implicit step lost energy every
// step), its centre follows y0 - g t^2 / 2 to 1e-9 m (the trapezoid rule is
// exact for it), and its gyroscopic flag is still set after each step.
TEST_F(FreeFlightTest, AFallingBoxTurnsFreelyAndFallsByGravity) {
  World& w = makeTable(1.0 / 60.0);
  const double y0 = w.table().topHeight() + 1.0;
  Shape& box = w.addEntity(std::make_unique<SolidBox>("box", 0.3, 0.2, 0.1), 1.0, Material{}, btVector3(0, y0, 0), 0);
  btRigidBody& body = *box.body();
  body.setAngularVelocity(btVector3(0.3, 5.0, -0.2));
  const double start = spinEnergy(body);
  const int flags = body.getFlags();
  ASSERT_NE(flags & BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY, 0);
  for (int i = 0; i < 18; ++i) {
    w.step();
    EXPECT_NEAR(spinEnergy(body), start, 1e-12 * start) << w.time();
    EXPECT_NEAR(body.getCenterOfMassPosition().y(), y0 - 0.5 * test::kG * w.time() * w.time(), 1e-9) << w.time();
    EXPECT_EQ(body.getFlags(), flags);
  }
}

// A box resting on the table and spun about the vertical is in contact:
// friction slows it as before (its spin falls), and its flags are kept.
TEST_F(FreeFlightTest, ABodyInContactIsLeftToBullet) {
  World& w = makeTable(1.0 / 60.0);
  Shape& box = w.addEntity(std::make_unique<SolidBox>("box", 0.2, 0.1, 0.2), 1.0, Material{0.4, 0, 0, 0},
                           btVector3(0, w.table().topHeight() + 0.05, 0), 0);
  btRigidBody& body = *box.body();
  simulate(0.1);
  body.setAngularVelocity(btVector3(0, 3.0, 0));
  const int flags = body.getFlags();
  const double start = spinEnergy(body);
  simulate(0.1);
  EXPECT_LT(spinEnergy(body), 0.9 * start);
  EXPECT_EQ(body.getFlags(), flags);
}

}  // namespace
}  // namespace tabletop
