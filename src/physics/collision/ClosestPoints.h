#pragma once

#include <utility>
#include <vector>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>

namespace tabletop {

/// GJK's closest points of two convex shapes placed in the world (the
/// normal on B, from B towards A; a negative distance where they overlap).
btPointCollector closestPoints(const btConvexShape& a, const btTransform& placeA, const btConvexShape& b,
                               const btTransform& placeB);

/// A convex piece of a body's shape placed in the world; a null shape
/// stands for a plane (the floor), which closestOf takes as the plane.
using ConvexPiece = std::pair<const btConvexShape*, btTransform>;

/// The convex pieces of a body's shape in the world: itself, or a
/// compound's children (the table's top and legs); a plane as one piece
/// with no shape.
std::vector<ConvexPiece> convexPieces(const btCollisionObject& object);

/// The closest points of a piece of A and a piece of B, either of which
/// may be a plane (given as a null shape with its object), as
/// closestPoints gives them: the normal on B, from B towards A.
btPointCollector closestOf(const btConvexShape* shapeA, const btTransform& placeA, const btCollisionObject& a,
                           const btConvexShape* shapeB, const btTransform& placeB, const btCollisionObject& b);

/// How far apart, m, the world boxes of two pieces are at least (0 when
/// they overlap): no closer than their shapes.
double boxGap(const btConvexShape& a, const btTransform& placeA, const btConvexShape& b, const btTransform& placeB);

}  // namespace tabletop
