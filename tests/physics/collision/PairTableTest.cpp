// The pair table (src/physics/collision/PairTable.h): each pair of shape
// types once, looked up in either order, and the dispatcher of a pipeline
// finding each pair's points with the finder its row names.

#include "physics/collision/PairTable.h"

#include <set>
#include <utility>

#include <gtest/gtest.h>

#include "physics/Pipeline.h"
#include "physics/collision/SolidOnFaceAlgorithm.h"
#include "physics/collision/SolidOnPlaneAlgorithm.h"

namespace tabletop {
namespace {

TEST(PairTable, EachPairOfTypesHasOneRowFoundInEitherOrder) {
  std::set<std::pair<int, int>> seen;
  for (const PairRule* rule = pairRulesBegin(); rule != pairRulesEnd(); ++rule) {
    const auto key = std::minmax(rule->a, rule->b);
    EXPECT_TRUE(seen.insert(key).second) << "types " << rule->a << " and " << rule->b << " twice";
    for (const auto& [a, b] : {std::pair(rule->a, rule->b), std::pair(rule->b, rule->a)}) {
      const PairRule found = pairRule(a, b);
      EXPECT_EQ(found.finder, rule->finder);
      EXPECT_EQ(found.upkeep, rule->upkeep);
      EXPECT_EQ(found.seenAhead, rule->seenAhead);
    }
  }
}

TEST(PairTable, APairNotInTheTableIsBulletsAndKeepsItsPoints) {
  const PairRule rule = pairRule(CAPSULE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE);
  EXPECT_EQ(rule.finder, PointFinder::kBullet);
  EXPECT_EQ(rule.upkeep, PointUpkeep::kKept);
  EXPECT_TRUE(rule.seenAhead);
}

TEST(PairTable, BallsTouchAtOnePointWhateverTheirPartner) {
  for (const int other : {SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE, CYLINDER_SHAPE_PROXYTYPE,
                          CONVEX_HULL_SHAPE_PROXYTYPE, STATIC_PLANE_PROXYTYPE, COMPOUND_SHAPE_PROXYTYPE}) {
    EXPECT_EQ(pairRule(SPHERE_SHAPE_PROXYTYPE, other).upkeep, PointUpkeep::kDeepestOnly) << other;
  }
}

// A shape of each type the table names, and the finder the dispatcher
// gives each pair of them.
btCollisionShape* shapeOf(int type) {
  static btBoxShape box(btVector3(0.1, 0.1, 0.1));
  static btCylinderShape cylinder(btVector3(0.1, 0.1, 0.1));
  static btSphereShape sphere(0.1);
  static btStaticPlaneShape plane(btVector3(0, 1, 0), 0);
  static btConvexHullShape hull;
  if (hull.getNumPoints() == 0) {
    for (const btVector3& p : {btVector3(0, 0.1, 0), btVector3(0.1, 0, 0), btVector3(0, 0, 0.1), btVector3(-0.1, 0, -0.1)}) {
      hull.addPoint(p);
    }
  }
  switch (type) {
    case BOX_SHAPE_PROXYTYPE: return &box;
    case CYLINDER_SHAPE_PROXYTYPE: return &cylinder;
    case SPHERE_SHAPE_PROXYTYPE: return &sphere;
    case STATIC_PLANE_PROXYTYPE: return &plane;
    case CONVEX_HULL_SHAPE_PROXYTYPE: return &hull;
    default: return nullptr;
  }
}

TEST(PairTable, TheDispatcherFindsEachPairsPointsWithItsRowsFinder) {
  Pipeline pipeline(Settings{}, TableSpec{});
  for (const PairRule* rule = pairRulesBegin(); rule != pairRulesEnd(); ++rule) {
    btCollisionShape* a = shapeOf(rule->a);
    btCollisionShape* b = shapeOf(rule->b);
    if (a == nullptr || b == nullptr) continue;  // the compound is dispatched by Bullet's own algorithm
    for (const bool swapped : {false, true}) {
      btCollisionObject first, second;
      first.setCollisionShape(swapped ? b : a);
      second.setCollisionShape(swapped ? a : b);
      const btCollisionObjectWrapper wrap0(nullptr, first.getCollisionShape(), &first, first.getWorldTransform(), -1, -1);
      const btCollisionObjectWrapper wrap1(nullptr, second.getCollisionShape(), &second, second.getWorldTransform(), -1, -1);
      btCollisionAlgorithm* found =
          pipeline.dispatcher->findAlgorithm(&wrap0, &wrap1, nullptr, BT_CONTACT_POINT_ALGORITHMS);
      ASSERT_NE(found, nullptr);
      const bool onFace = dynamic_cast<SolidOnFaceAlgorithm*>(found) != nullptr;
      const bool onPlane = dynamic_cast<SolidOnPlaneAlgorithm*>(found) != nullptr;
      EXPECT_EQ(onFace, rule->finder == PointFinder::kSolidOnFace) << rule->a << " x " << rule->b;
      EXPECT_EQ(onPlane, rule->finder == PointFinder::kSolidOnPlane) << rule->a << " x " << rule->b;
      found->~btCollisionAlgorithm();
      pipeline.dispatcher->freeCollisionAlgorithm(found);
    }
  }
}

}  // namespace
}  // namespace tabletop
