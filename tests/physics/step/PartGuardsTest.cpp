// The guards a part sets Bullet's contact points and solver with: whatever
// a solve changed under a guard is back as the guard ends, on every path,
// and a value held twice gets its first back.

#include "physics/step/PartGuards.h"

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace tabletop {
namespace {

struct TwoPoints {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btSphereShape ball{0.05};
  btCollisionObject a, b;
  btPersistentManifold* manifold = nullptr;
  TwoPoints() {
    a.setCollisionShape(&ball);
    b.setCollisionShape(&ball);
    manifold = dispatcher.getNewManifold(&a, &b);
    for (const double gap : {0.001, 0.002}) {
      btManifoldPoint point(btVector3(0, 0, 0), btVector3(0, 0, 0), btVector3(0, 1, 0), gap);
      point.m_positionWorldOnA = btVector3(gap, 0, 0);
      point.m_positionWorldOnB = btVector3(0, gap, 0);
      point.m_appliedImpulse = 10 * gap;
      point.m_appliedImpulseLateral1 = 20 * gap;
      point.m_appliedImpulseLateral2 = 30 * gap;
      manifold->addManifoldPoint(point);
    }
  }
  ~TwoPoints() { dispatcher.releaseManifold(manifold); }
  btManifoldPoint& point(int p) { return manifold->getContactPoint(p); }
};

TEST(PartGuards, GapsAndPlacesHeldForASolveComeBackEvenThroughAnException) {
  TwoPoints c;
  HeldGaps::Storage gapStorage;
  HeldPlaces::Storage placeStorage;
  try {
    HeldGaps gaps(gapStorage);
    HeldPlaces places(placeStorage);
    // Point 0 held twice: the first value is the one put back.
    gaps.storage().emplace_back(&c.point(0), c.point(0).getDistance());
    c.point(0).setDistance(0.5);
    gaps.storage().emplace_back(&c.point(0), c.point(0).getDistance());
    c.point(0).setDistance(0.7);
    places.storage().push_back({&c.point(1), c.point(1).m_positionWorldOnA, c.point(1).m_positionWorldOnB});
    c.point(1).m_positionWorldOnA = btVector3(1, 1, 1);
    c.point(1).m_positionWorldOnB = btVector3(2, 2, 2);
    throw std::runtime_error("a solve that fails");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(c.point(0).getDistance(), btScalar(0.001));
  EXPECT_EQ(c.point(1).m_positionWorldOnA, btVector3(0.002, 0, 0));
  EXPECT_EQ(c.point(1).m_positionWorldOnB, btVector3(0, 0.002, 0));
  EXPECT_TRUE(gapStorage.empty());
  EXPECT_TRUE(placeStorage.empty());
}

TEST(PartGuards, KeptImpulsesAreTheGivenOnesOnlyWhenAsked) {
  TwoPoints c;
  KeptImpulses::Storage storage;
  for (const bool keep : {true, false}) {
    {
      const KeptImpulses kept(storage, c.dispatcher, keep);
      c.point(1).m_appliedImpulse = 5;
      c.point(1).m_appliedImpulseLateral1 = 6;
      c.point(1).m_appliedImpulseLateral2 = 7;
    }
    EXPECT_EQ(c.point(1).m_appliedImpulse, keep ? btScalar(0.02) : btScalar(5));
    EXPECT_EQ(c.point(1).m_appliedImpulseLateral1, keep ? btScalar(0.04) : btScalar(6));
    EXPECT_EQ(c.point(1).m_appliedImpulseLateral2, keep ? btScalar(0.06) : btScalar(7));
  }
}

TEST(PartGuards, IterationsAndFrictionAlongALineLastOneSolve) {
  btContactSolverInfo info;
  info.m_numIterations = 10;
  {
    const IterationsFor more(info, 50);
    EXPECT_EQ(info.m_numIterations, 50);
  }
  EXPECT_EQ(info.m_numIterations, 10);

  TwoPoints c;
  c.point(0).m_contactPointFlags = BT_CONTACT_FLAG_HAS_CONTACT_CFM;  // a flag of Bullet's own, kept
  {
    const FrictionAlongLine held({&c.point(0)});
    c.point(0).m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED | kFirstFrictionRowOnly;
  }
  EXPECT_EQ(c.point(0).m_contactPointFlags, BT_CONTACT_FLAG_HAS_CONTACT_CFM);
}

}  // namespace
}  // namespace tabletop
