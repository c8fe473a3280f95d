// RollingLines (src/physics/step/RollingLines.h) on hand-built contacts: a
// cone 0.05 x 0.1 m lying on a fixed plane, touching it at its apex (the
// origin) and at its base's rim, its slant side along +x.
//  - findLines: the cone's two points make its line; a box's, a standing
//    cone's (a chord of its rim) or three points off one line make none;
//  - transport: rolled about its line, then turned 0.03 rad about the
//    vertical through its apex, its spin turns with the line, and its
//    velocity still rolls about it (1e-12 m/s at the line's middle); a
//    kicked body, or a line that jumped, is left alone;
//  - turnAt: over a 60 Hz part, turned as its axis precesses and spins,
//    its apex stays on the plane where it was (1e-12 m) and its axis keeps
//    its half angle to the plane (1e-12 rad) and turns about the vertical
//    by -w tan(a) dt (1e-12 rad), where turning about its starting line
//    tilts it by 1.1e-3 rad.

#include "physics/step/RollingLines.h"

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "physics/shapes/Cylinder.h"

namespace tabletop {
namespace {

constexpr double kR = 0.05, kH = 0.1;
constexpr double kDt = 1.0 / 60.0;
const double kHalf = std::atan(kR / kH);   // rad
const double kSlant = std::hypot(kR, kH);  // m
constexpr double kApexY = 0.75 * kH;       // m, the apex on the body's y axis

struct Scene {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  Cylinder cone{"cone", kR, 0.0, kH};
  btBoxShape boxShape{btVector3(0.05, 0.05, 0.05)};
  btStaticPlaneShape planeShape{btVector3(0, 1, 0), 0};
  std::unique_ptr<btRigidBody> body;
  btCollisionObject plane;
  BodySet none;

  // The cone lying with its slant side along +x from the apex at the
  // origin, turned `yaw` about the vertical through the apex.
  explicit Scene(double yaw = 0, bool box = false) {
    body = std::make_unique<btRigidBody>(1.0, nullptr, box ? static_cast<btCollisionShape*>(&boxShape)
                                                           : &cone.collisionShape(), btVector3(1, 1, 1));
    plane.setCollisionShape(&planeShape);
    plane.setCollisionFlags(btCollisionObject::CF_STATIC_OBJECT);
    plane.setWorldArrayIndex(0);
    body->setWorldArrayIndex(1);
    place(yaw);
  }
  ~Scene() {
    while (dispatcher.getNumManifolds() > 0) dispatcher.releaseManifold(dispatcher.getManifoldByIndexInternal(0));
  }
  static btQuaternion turn(double yaw) { return btQuaternion(btVector3(0, 1, 0), yaw); }
  // The pose and the two points of the cone turned by `yaw`.
  void place(double yaw) {
    const btVector3 axis = quatRotate(turn(yaw), btVector3(-std::cos(kHalf), -std::sin(kHalf), 0));
    const btQuaternion lying(btVector3(0, 0, 1), std::atan2(std::cos(kHalf), -std::sin(kHalf)));
    body->setWorldTransform(btTransform(turn(yaw) * lying, -axis * kApexY));
    while (dispatcher.getNumManifolds() > 0) dispatcher.releaseManifold(dispatcher.getManifoldByIndexInternal(0));
    touch({btVector3(0, 0, 0), quatRotate(turn(yaw), btVector3(kSlant, 0, 0))});
  }
  void touch(std::initializer_list<btVector3> points) {
    btPersistentManifold* manifold = dispatcher.getNewManifold(body.get(), &plane);
    for (const btVector3& at : points) {
      btManifoldPoint point(body->getWorldTransform().invXform(at), at, btVector3(0, 1, 0), 0);
      point.m_positionWorldOnA = at;
      point.m_positionWorldOnB = at;
      manifold->addManifoldPoint(point);
    }
  }
  // Rolling about its line at `w` rad/s: the spin along it, the centre
  // moving as spin x (centre - apex), the apex at the origin.
  void roll(double w) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(0);
    const btVector3 along =
        (m->getContactPoint(1).getPositionWorldOnA() - m->getContactPoint(0).getPositionWorldOnA()).normalized();
    body->setAngularVelocity(w * along);
    body->setLinearVelocity((w * along).cross(body->getCenterOfMassPosition()));
  }
};

TEST(RollingLines, AConeLyingOnItsSideTouchesAlongALine) {
  Scene scene;
  RollingLines lines;
  const auto& found = lines.findLines(scene.dispatcher);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].support, &scene.plane);
  EXPECT_NEAR(found[0].normal.y(), 1.0, 1e-12);
  EXPECT_NEAR(found[0].a.distance(found[0].b), kSlant, 1e-12);
}

TEST(RollingLines, NoLineForABoxAStandingConeOrPointsOffALine) {
  Scene box(0, true);
  RollingLines lines;
  EXPECT_TRUE(lines.findLines(box.dispatcher).empty());

  Scene standing;
  standing.body->setWorldTransform(btTransform(btQuaternion::getIdentity(), btVector3(0, 0.25 * kH, 0)));
  while (standing.dispatcher.getNumManifolds() > 0) {
    standing.dispatcher.releaseManifold(standing.dispatcher.getManifoldByIndexInternal(0));
  }
  standing.touch({btVector3(-0.03, 0, -0.04), btVector3(0.03, 0, -0.04)});  // a chord of its base's rim
  EXPECT_TRUE(lines.findLines(standing.dispatcher).empty());

  Scene three;
  three.touch({btVector3(0.05, 0, 0.01)});  // 1 cm off the slant side
  EXPECT_TRUE(lines.findLines(three.dispatcher).empty());
}

TEST(RollingLines, ARolledVelocityTurnsWithItsLine) {
  Scene scene;
  scene.roll(4.0);
  RollingLines lines;
  lines.record(scene.dispatcher, scene.none);
  const btVector3 spin = scene.body->getAngularVelocity();
  const btVector3 linear = scene.body->getLinearVelocity();
  const double yaw = 0.03;
  scene.place(yaw);
  const auto& moved = lines.transport(scene.dispatcher, scene.none);
  ASSERT_EQ(moved.size(), 1u);
  const btVector3 turned = quatRotate(Scene::turn(yaw), spin);
  EXPECT_LT((scene.body->getAngularVelocity() - turned).length(), 1e-12);
  const btVector3 middle = quatRotate(Scene::turn(yaw), btVector3(0.5 * kSlant, 0, 0));
  const btVector3 atMiddle = scene.body->getLinearVelocity() +
                             scene.body->getAngularVelocity().cross(middle - scene.body->getCenterOfMassPosition());
  EXPECT_LT(atMiddle.length(), 1e-12);
  EXPECT_NEAR(scene.body->getLinearVelocity().length(), linear.length(), 1e-12);
}

TEST(RollingLines, AKickedBodyOrALineThatJumpedIsLeftAlone) {
  Scene kicked;
  kicked.roll(4.0);
  RollingLines lines;
  lines.record(kicked.dispatcher, kicked.none);
  kicked.place(0.03);
  BodySet pushed;
  pushed.insert(kicked.body.get());
  EXPECT_TRUE(lines.transport(kicked.dispatcher, pushed).empty());

  Scene jumped;
  jumped.roll(4.0);
  RollingLines again;
  again.record(jumped.dispatcher, jumped.none);
  jumped.place(0.6);
  EXPECT_TRUE(again.transport(jumped.dispatcher, jumped.none).empty());
}

TEST(RollingLines, APartTurnsItAsItsAxisPrecessesAndSpins) {
  Scene scene;
  scene.roll(4.0);
  RollingLines lines;
  lines.record(scene.dispatcher, scene.none);
  ASSERT_TRUE(lines.turning());
  const btTransform start = scene.body->getWorldTransform();
  btTransform pose = start;
  ASSERT_TRUE(lines.turnAt(*scene.body, start, scene.body->getLinearVelocity(), scene.body->getAngularVelocity(),
                           kDt, pose));
  const btVector3 apex = pose * btVector3(0, kApexY, 0);
  EXPECT_LT(apex.length(), 1e-12);
  const btVector3 axis = pose.getBasis().getColumn(1);
  EXPECT_NEAR(std::asin(-axis.y()), kHalf, 1e-12);
  EXPECT_NEAR(std::atan2(axis.z(), -axis.x()), -4.0 * std::tan(kHalf) * kDt, 1e-12);
  // Turned about its starting line instead, it tilts by tan(a) (w dt)^2 / 2.
  btTransform fixedLine = start;
  fixedLine.setRotation(btQuaternion(btVector3(1, 0, 0), 4.0 * kDt) * start.getRotation());
  EXPECT_GT(std::abs(std::asin(-fixedLine.getBasis().getColumn(1).y()) - kHalf), 1e-3);
}

}  // namespace
}  // namespace tabletop
