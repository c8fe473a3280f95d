// The settled window judges tabletop and Bullet alike: its drift, its
// deepest contact and its energy gain, checked on one free body moved by hand.

#include "measure/SettledWatch.h"

#include <cmath>

#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

namespace tabletop {
namespace {

TEST(SettledWatch, MeasuresOnlyInsideItsWindow) {
  btSphereShape shape(0.1);
  btVector3 inertia;
  shape.calculateLocalInertia(2.0, inertia);
  btRigidBody body(btRigidBody::btRigidBodyConstructionInfo(2.0, nullptr, &shape, inertia));
  const std::vector<const btRigidBody*> bodies{&body};
  SettledWatch watch(1.0, 2.0, 9.81);
  // Before the window: moves, sinks and speeds that must not count.
  body.getWorldTransform().setOrigin(btVector3(5, 1, 0));
  body.setLinearVelocity(btVector3(10, 0, 0));
  watch.observe(0.5, bodies, 0.3);
  // In it: 1 m/s along z for 1 s (kinetic 1 J), 3 mm deep at most, then
  // lifted 0.1 m: 2 kg x 9.81 x 0.1 = 1.962 J gained over the lowest.
  body.setLinearVelocity(btVector3(0, 0, 1));
  body.getWorldTransform().setOrigin(btVector3(0, 1, 0));
  watch.observe(1.0, bodies, 0.001);
  body.getWorldTransform().setOrigin(btVector3(0, 1, 0.5));
  watch.observe(1.5, bodies, 0.003);
  EXPECT_FALSE(watch.result().measured);
  body.getWorldTransform().setOrigin(btVector3(0, 1.1, 1.0));
  watch.observe(2.0, bodies, 0.002);
  // After it: nothing changes any more.
  body.getWorldTransform().setOrigin(btVector3(9, 9, 9));
  watch.observe(2.5, bodies, 1.0);
  const Settled& s = watch.result();
  EXPECT_TRUE(s.measured);
  EXPECT_NEAR(s.drift, std::sqrt(1.0 + 0.01), 1e-12);
  EXPECT_DOUBLE_EQ(s.penetration, 0.003);
  EXPECT_NEAR(s.energyGain, 2.0 * 9.81 * 0.1, 1e-9);
  EXPECT_NEAR(mechanicalEnergy(body, 9.81), 0.5 * 2.0 * 1.0 + 2.0 * 9.81 * 9.0, 1e-9);
}

}  // namespace
}  // namespace tabletop
