#include "physics/ContactResult.h"

#include <algorithm>

namespace tabletop {
namespace {

// The merge radius is this share of the smallest extent.
constexpr double kShareOfExtent = 0.5;

// The smallest extent of a shape's own bounding box, m (a plane's is huge).
double smallestExtent(const btCollisionShape& shape) {
  btTransform identity;
  identity.setIdentity();
  btVector3 low, high;
  shape.getAabb(identity, low, high);
  const btVector3 extent = high - low;
  return std::min({extent.x(), extent.y(), extent.z()});
}

// The kept point of `manifold` nearest `point` and within `radius` of it,
// or -1, measured on a body that moves (body A, unless it is static): a
// corner sliding over the floor stays the same corner of the box, though
// it is a new place on the floor every step.
int keptPointWithin(const btPersistentManifold& manifold, const btManifoldPoint& point, double radius) {
  const bool onB = manifold.getBody0()->isStaticOrKinematicObject();
  int nearest = -1;
  double nearestSquared = radius * radius;
  for (int p = 0; p < manifold.getNumContacts(); ++p) {
    const btManifoldPoint& kept = manifold.getContactPoint(p);
    const double squared = onB ? (kept.m_localPointB - point.m_localPointB).length2()
                               : (kept.m_localPointA - point.m_localPointA).length2();
    if (squared < nearestSquared) {
      nearestSquared = squared;
      nearest = p;
    }
  }
  return nearest;
}

}  // namespace

ContactResult::ContactResult(const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1)
    : btManifoldResult(body0, body1) {}

double ContactResult::mergeRadius(const btCollisionShape& a, const btCollisionShape& b, double breakingThreshold) {
  return std::min(breakingThreshold, kShareOfExtent * std::min(smallestExtent(a), smallestExtent(b)));
}

void ContactResult::addContactPoint(const btVector3& normalOnBInWorld, const btVector3& pointInWorld,
                                    btScalar depth) {
  btPersistentManifold& manifold = *m_manifoldPtr;
  if (depth > manifold.getContactBreakingThreshold()) return;

  // The manifold's body A may be this result's body 1.
  const bool swapped = manifold.getBody0() != m_body0Wrap->getCollisionObject();
  const btCollisionObjectWrapper& a = swapped ? *m_body1Wrap : *m_body0Wrap;
  const btCollisionObjectWrapper& b = swapped ? *m_body0Wrap : *m_body1Wrap;
  const btVector3 pointOnA = pointInWorld + normalOnBInWorld * depth;
  btManifoldPoint point(a.getCollisionObject()->getWorldTransform().invXform(pointOnA),
                        b.getCollisionObject()->getWorldTransform().invXform(pointInWorld), normalOnBInWorld,
                        depth);
  point.m_positionWorldOnA = pointOnA;
  point.m_positionWorldOnB = pointInWorld;

  // The pair's material, as Bullet combines it.
  const btCollisionObject* object0 = m_body0Wrap->getCollisionObject();
  const btCollisionObject* object1 = m_body1Wrap->getCollisionObject();
  point.m_combinedFriction = gCalculateCombinedFrictionCallback(object0, object1);
  point.m_combinedRestitution = gCalculateCombinedRestitutionCallback(object0, object1);
  point.m_combinedRollingFriction = gCalculateCombinedRollingFrictionCallback(object0, object1);
  point.m_combinedSpinningFriction = gCalculateCombinedSpinningFrictionCallback(object0, object1);
  const int flags = object0->getCollisionFlags() | object1->getCollisionFlags();
  if (flags & btCollisionObject::CF_HAS_CONTACT_STIFFNESS_DAMPING) {
    point.m_combinedContactDamping1 = gCalculateCombinedContactDampingCallback(object0, object1);
    point.m_combinedContactStiffness1 = gCalculateCombinedContactStiffnessCallback(object0, object1);
    point.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
  }
  if (flags & btCollisionObject::CF_HAS_FRICTION_ANCHOR) point.m_contactPointFlags |= BT_CONTACT_FLAG_FRICTION_ANCHOR;
  btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
  point.m_partId0 = swapped ? m_partId1 : m_partId0;
  point.m_partId1 = swapped ? m_partId0 : m_partId1;
  point.m_index0 = swapped ? m_index1 : m_index0;
  point.m_index1 = swapped ? m_index0 : m_index1;

  const int kept = keptPointWithin(
      manifold, point,
      mergeRadius(*a.getCollisionShape(), *b.getCollisionShape(), manifold.getContactBreakingThreshold()));
  if (kept >= 0) {
    manifold.replaceContactPoint(point, kept);
  } else {
    manifold.addManifoldPoint(point);
  }
}

}  // namespace tabletop
