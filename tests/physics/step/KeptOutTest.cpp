// KeptOut (src/physics/step/KeptOut.h) on a hand-built contact: a box
// 1 kg resting on a fixed plane, one of its corners apart from it by a
// gap at the part's start. Held by its row (closing no faster than the gap
// allows) and carried past the plane by the integration, the corner ends
// on the plane (1e-12 m); a lack under kSlack, a corner already touching,
// one the solve let in, and a support that moves are left alone.

#include "physics/step/KeptOut.h"

#include <gtest/gtest.h>

namespace tabletop {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kGap = 5e-5;  // m

struct Scene {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btBoxShape boxShape{btVector3(0.05, 0.05, 0.05)};
  btStaticPlaneShape planeShape{btVector3(0, 1, 0), 0};
  btRigidBody box{1.0, nullptr, &boxShape, btVector3(1, 1, 1)};
  btCollisionObject plane;
  btAlignedObjectArray<btRigidBody*> bodies;
  btVector3 corner{0.05, -0.05, 0.05};  // on the box

  // The box with its lowest corner `gap` above the plane, closing at
  // `speed` (m/s, downwards), the support fixed or not.
  explicit Scene(double gap, double speed, bool fixed = true) {
    plane.setCollisionShape(&planeShape);
    plane.setCollisionFlags(fixed ? btCollisionObject::CF_STATIC_OBJECT : 0);
    plane.setWorldArrayIndex(0);
    box.setWorldArrayIndex(1);
    box.setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0.05 + gap, 0)));
    box.setLinearVelocity(btVector3(0, -speed, 0));
    bodies.push_back(&box);
    btPersistentManifold* manifold = dispatcher.getNewManifold(&box, &plane);
    const btVector3 onBox = box.getWorldTransform() * corner;
    btManifoldPoint point(corner, onBox - btVector3(0, gap, 0), btVector3(0, 1, 0), gap);
    point.m_positionWorldOnA = onBox;
    point.m_positionWorldOnB = onBox - btVector3(0, gap, 0);
    manifold->addManifoldPoint(point);
  }
  ~Scene() {
    while (dispatcher.getNumManifolds() > 0) dispatcher.releaseManifold(dispatcher.getManifoldByIndexInternal(0));
  }
  // The corner's height above the plane once the box is moved `down`
  // (m) by the integration and kept out.
  double cornerAfter(double down) {
    KeptOut kept;
    kept.collect(dispatcher, bodies, kDt);
    const btTransform start = box.getWorldTransform();
    btTransform pose = start;
    pose.setOrigin(start.getOrigin() - btVector3(0, down, 0));
    kept.keepOut(0, start, pose);
    return (pose * corner).y();
  }
};

TEST(KeptOut, ACornerTheSolveHeldAtTheSupportEndsOnIt) {
  // The row let it close by the gap over the part; the mean of its start
  // speed (twice that) and its end speed carries it 1.5 gaps down.
  Scene scene(kGap, kGap / kDt);
  EXPECT_NEAR(scene.cornerAfter(1.5 * kGap), 0.0, 1e-12);
}

TEST(KeptOut, ALackUnderTheSlackIsLeftAlone) {
  Scene scene(kGap, kGap / kDt);
  const double lack = 0.5 * KeptOut::kSlack;
  EXPECT_NEAR(scene.cornerAfter(kGap + lack), -lack, 1e-12);
}

TEST(KeptOut, ACornerStillApartIsNotMoved) {
  Scene scene(kGap, 0.0);
  EXPECT_NEAR(scene.cornerAfter(0.5 * kGap), 0.5 * kGap, 1e-12);
}

TEST(KeptOut, ACornerTheSolveLetInIsNotHeld) {
  // Closing at twice what the gap allows at the part's end: the solve
  // let it in (an impact, a push out of the support to come).
  Scene scene(kGap, 2 * kGap / kDt);
  EXPECT_NEAR(scene.cornerAfter(2 * kGap), -kGap, 1e-12);
}

TEST(KeptOut, OnlyFixedSupportsHold) {
  Scene scene(kGap, kGap / kDt, false);
  EXPECT_NEAR(scene.cornerAfter(1.5 * kGap), -0.5 * kGap, 1e-12);
}

TEST(KeptOut, ACornerAlreadyTouchingIsNotHeld) {
  Scene scene(0.0, 0.0);
  EXPECT_NEAR(scene.cornerAfter(kGap), -kGap, 1e-12);
}

}  // namespace
}  // namespace tabletop
