#include "physics/collision/ClosestPoints.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include <algorithm>

namespace tabletop {
namespace {

// The closest points of a convex piece and a plane (the floor), as
// closestPoints gives them for two pieces with the plane as B: its normal,
// the piece's point deepest along it, and that point's foot on the plane.
btPointCollector closestToPlane(const btConvexShape& shape, const btTransform& place, const btCollisionObject& plane) {
  const auto& planeShape = static_cast<const btStaticPlaneShape&>(*plane.getCollisionShape());
  const btTransform& planePlace = plane.getWorldTransform();
  const btVector3 normal = planePlace.getBasis() * planeShape.getPlaneNormal();
  const btScalar level = planeShape.getPlaneConstant() + normal.dot(planePlace.getOrigin());
  const btVector3 deepest = place * shape.localGetSupportingVertex(place.getBasis().transpose() * -normal);
  const btScalar distance = normal.dot(deepest) - level;
  btPointCollector closest;
  closest.addContactPoint(normal, deepest - normal * distance, distance);
  return closest;
}

}  // namespace

btPointCollector closestPoints(const btConvexShape& a, const btTransform& placeA, const btConvexShape& b,
                               const btTransform& placeB) {
  btVoronoiSimplexSolver simplex;
  btGjkEpaPenetrationDepthSolver depth;
  btGjkPairDetector gjk(&a, &b, &simplex, &depth);
  btDiscreteCollisionDetectorInterface::ClosestPointInput input;
  input.m_transformA = placeA;
  input.m_transformB = placeB;
  btPointCollector closest;
  gjk.getClosestPoints(input, closest, nullptr);
  return closest;
}

std::vector<ConvexPiece> convexPieces(const btCollisionObject& object) {
  std::vector<ConvexPiece> pieces;
  const btCollisionShape* shape = object.getCollisionShape();
  if (shape->isConvex()) {
    pieces.emplace_back(static_cast<const btConvexShape*>(shape), object.getWorldTransform());
  } else if (shape->getShapeType() == STATIC_PLANE_PROXYTYPE) {
    pieces.emplace_back(nullptr, object.getWorldTransform());  // closestOf takes it as a plane
  } else if (shape->isCompound()) {
    const auto* compound = static_cast<const btCompoundShape*>(shape);
    for (int c = 0; c < compound->getNumChildShapes(); ++c) {
      if (!compound->getChildShape(c)->isConvex()) continue;
      pieces.emplace_back(static_cast<const btConvexShape*>(compound->getChildShape(c)),
                          object.getWorldTransform() * compound->getChildTransform(c));
    }
  }
  return pieces;
}

btPointCollector closestOf(const btConvexShape* shapeA, const btTransform& placeA, const btCollisionObject& a,
                           const btConvexShape* shapeB, const btTransform& placeB, const btCollisionObject& b) {
  if (shapeB == nullptr) return closestToPlane(*shapeA, placeA, b);
  if (shapeA != nullptr) return closestPoints(*shapeA, placeA, *shapeB, placeB);
  // A is the plane: B's deepest point is on B, the normal from B to A.
  const btPointCollector fromPlane = closestToPlane(*shapeB, placeB, a);
  btPointCollector closest;
  closest.addContactPoint(-fromPlane.m_normalOnBInWorld,
                          fromPlane.m_pointInWorld + fromPlane.m_normalOnBInWorld * fromPlane.m_distance,
                          fromPlane.m_distance);
  return closest;
}

double boxGap(const btConvexShape& a, const btTransform& placeA, const btConvexShape& b, const btTransform& placeB) {
  btVector3 lowA, highA, lowB, highB;
  a.getAabb(placeA, lowA, highA);
  b.getAabb(placeB, lowB, highB);
  btVector3 apart(0, 0, 0);
  for (int i = 0; i < 3; ++i) apart[i] = std::max({0.0, lowB[i] - highA[i], lowA[i] - highB[i]});
  return apart.length();
}

}  // namespace tabletop
