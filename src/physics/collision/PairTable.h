#pragma once

#include <btBulletCollisionCommon.h>

namespace tabletop {

/// The pair table: for two Bullet shape types, what finds their contact
/// points and how a part keeps them. The one place that knows pairs of
/// shapes (as MuJoCo's collision function table): ContactDispatcher
/// registers the finders from it, the step drops points by it.

/// What finds a pair's points.
enum class PointFinder {
  kBullet,        ///< Bullet's default algorithm for the pair
  kSolidOnFace,   ///< SolidOnFaceAlgorithm: a face's corners while one rests on the other's face
  kSolidOnPlane,  ///< SolidOnPlaneAlgorithm: the corners nearest the floor
};

/// What SolidOnFaceAlgorithm falls back on where no face rests on a face.
enum class FaceFallback {
  kNone,
  kConvexConvex,   ///< Bullet's convex-convex algorithm (SAT clipping for polyhedra)
  kMultipointGjk,  ///< the same with Bullet's perturbation: a whole face in one step
};

/// How a part treats the points of a pair's manifold before its solve.
enum class PointUpkeep {
  kKept,         ///< as Bullet keeps them, from step to step
  kFoundAfresh,  ///< every touching point is found again each step: one that slid is stale and dropped
  kDeepestOnly,  ///< a ball touches at one point: only the deepest stays
};

struct PairRule {
  int a, b;  ///< Bullet shape types (BroadphaseNativeTypes); either order
  PointFinder finder;
  FaceFallback otherwise;
  PointUpkeep upkeep;
  /// Points are made up to the breaking threshold ahead of touching (every
  /// pair but two balls gets this from its algorithm).
  bool seenAhead;
};

/// The rows of the table, each pair of types once.
const PairRule* pairRulesBegin();
const PairRule* pairRulesEnd();

/// The rule for two shape types, in either order; a pair that is not in
/// the table is found by Bullet and its points kept.
PairRule pairRule(int typeA, int typeB);
inline PairRule pairRule(const btCollisionObject& a, const btCollisionObject& b) {
  return pairRule(a.getCollisionShape()->getShapeType(), b.getCollisionShape()->getShapeType());
}

}  // namespace tabletop
