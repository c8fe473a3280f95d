// ImpactScan on hand-built contact points: when a point still apart meets,
// from its gap, closing speed and the bodies' forces, against the closed
// forms of motion under constant acceleration and of two balls meeting.

#include "physics/step/ImpactSearch.h"

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "support/HandBuiltContacts.h"

namespace tabletop {
namespace {

constexpr double kG = 9.81;  // m/s^2

std::unique_ptr<btRigidBody> weighted(btCollisionShape& shape, double mass, const btVector3& at, const btVector3& v) {
  return test::movingBody(shape, mass, at, v, kG);
}

// A point of `manifold` `gap` m below A's `onA`, the normal on B up.
void addPointBelow(btPersistentManifold& manifold, const btVector3& onA, double gap) {
  const btVector3 onB = onA - btVector3(0, gap, 0);
  btManifoldPoint point(onA, onB, btVector3(0, 1, 0), gap);
  point.m_positionWorldOnA = onA;
  point.m_positionWorldOnB = onB;
  manifold.addManifoldPoint(point);
}

struct Floor {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btStaticPlaneShape planeShape{btVector3(0, 1, 0), 0};
  btCollisionObject plane;
  Floor() { plane.setCollisionShape(&planeShape); }
};

// A falling box's corner `gap` above the floor, closing at v0 under
// gravity, meets it at the first root of gap = v0 t + g t^2 / 2; a scan
// that finds nothing by the horizon returns the horizon, and one whose
// point would arrive slower than the impact speed is no impact.
TEST(ImpactScan, AFallingPointMeetsAtTheRootOfItsUniformlyAcceleratedGap) {
  for (const double gap : {1e-4, 2e-3, 1.5e-2}) {
    for (const double v0 : {0.0, 0.3, 2.0}) {
      Floor floor;
      btBoxShape shape(btVector3(0.05, 0.05, 0.05));
      auto box = weighted(shape, 0.7, btVector3(0, 0.05 + gap, 0), btVector3(0.2, -v0, 0));
      btPersistentManifold* manifold = floor.dispatcher.getNewManifold(box.get(), &floor.plane);
      addPointBelow(*manifold, btVector3(0.05, gap, 0.05), gap);
      ImpactScan::Storage storage;
      const ImpactScan scan(floor.dispatcher, storage);
      const double expected = (-v0 + std::sqrt(v0 * v0 + 2 * kG * gap)) / kG;
      const std::string where = "gap " + std::to_string(gap) + " m, v0 " + std::to_string(v0) + " m/s";
      EXPECT_NEAR(scan.closingAcceleration(*manifold, manifold->getContactPoint(0)), kG, 1e-12) << where;
      EXPECT_NEAR(scan.earliestImpact(1.0, 0.0), expected, 1e-12) << where;
      EXPECT_EQ(scan.earliestImpact(0.5 * expected, 0.0), 0.5 * expected) << where;
      const double arrival = v0 + kG * expected;
      EXPECT_EQ(scan.earliestImpact(1.0, 1.01 * arrival), 1.0) << where;
      floor.dispatcher.releaseManifold(manifold);
    }
  }
}

// A body that something touches is held: its supports make its motion
// other than its forces say, so its points still apart close at their
// present speed alone (gap / v0), and a touching point is no impact.
TEST(ImpactScan, ATouchedBodyIsTakenNotToAccelerate) {
  Floor floor;
  btBoxShape shape(btVector3(0.05, 0.05, 0.05));
  auto box = weighted(shape, 0.7, btVector3(0, 0.05, 0), btVector3(0, -0.4, 0));
  btPersistentManifold* manifold = floor.dispatcher.getNewManifold(box.get(), &floor.plane);
  addPointBelow(*manifold, btVector3(-0.05, 0, -0.05), 0.0);
  addPointBelow(*manifold, btVector3(0.05, 3e-3, 0.05), 3e-3);
  ImpactScan::Storage storage;
  const ImpactScan scan(floor.dispatcher, storage);
  EXPECT_EQ(scan.closingAcceleration(*manifold, manifold->getContactPoint(1)), 0.0);
  EXPECT_NEAR(scan.earliestImpact(1.0, 0.0), 3e-3 / 0.4, 1e-15);
  floor.dispatcher.releaseManifold(manifold);
}

// Two balls in free flight (no forces) meet when their centres are the sum
// of their radii apart, |r + v t| = R, not when the gap along the first
// normal closes: for an oblique approach the two differ.
TEST(ImpactScan, TwoBallsMeetWhenTheirCentresAreTheSumOfTheRadiiApart) {
  for (const double offset : {0.0, 0.02, 0.04}) {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher(&configuration);
    btSphereShape small(0.02), large(0.03);
    auto a = weighted(small, 0.2, btVector3(0, 0.5, 0), btVector3(1.5, 0, 0));
    auto b = weighted(large, 0.3, btVector3(0.08, 0.5, offset), btVector3(0, 0, 0));
    a->clearForces();
    b->clearForces();
    btPersistentManifold* manifold = dispatcher.getNewManifold(a.get(), b.get());
    const btVector3 r = a->getWorldTransform().getOrigin() - b->getWorldTransform().getOrigin();
    const btVector3 n = r.normalized();
    const double gap = r.length() - 0.05;
    btManifoldPoint point(btVector3(0, 0, 0), btVector3(0, 0, 0), n, gap);
    point.m_positionWorldOnA = a->getWorldTransform().getOrigin() - n * 0.02;
    point.m_positionWorldOnB = b->getWorldTransform().getOrigin() + n * 0.03;
    manifold->addManifoldPoint(point);
    ImpactScan::Storage storage;
    const ImpactScan scan(dispatcher, storage);
    // |r + v t| = R with v = (1.5, 0, 0): the first root.
    const double v = 1.5, rv = r.x() * v, rr = r.length2(), reach = 0.05;
    const double expected = (-rv - std::sqrt(rv * rv - v * v * (rr - reach * reach))) / (v * v);
    EXPECT_NEAR(scan.earliestImpact(1.0, 0.0), expected, 1e-12) << "offset " << offset << " m";
    dispatcher.releaseManifold(manifold);
  }
}

}  // namespace
}  // namespace tabletop
