#include "physics/step/ImpactSearch.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "physics/collision/ClosestPoints.h"
#include "physics/contact/PointFlags.h"
#include "physics/shapes/ShapeKinds.h"

namespace tabletop {
namespace {

// When two balls moving at their present velocities meet: where their
// centres are the sum of the radii apart, |r + v t| = R. The gap along the
// normal of the part's start closes at v.n, but that normal turns as an
// oblique approach goes on, so the gap's own time came early and the
// bounce, taken where the balls were still micrometres apart, was along a
// normal a little off (5e-4 m/s at 55 degrees). None if either is not a
// ball or they do not meet.
std::optional<double> ballsMeet(const btPersistentManifold& manifold) {
  const btCollisionObject* a = manifold.getBody0();
  const btCollisionObject* b = manifold.getBody1();
  if (!isBall(*a) || !isBall(*b)) return std::nullopt;
  const double reach = static_cast<const btSphereShape*>(a->getCollisionShape())->getRadius() +
                       static_cast<const btSphereShape*>(b->getCollisionShape())->getRadius();
  const btVector3 r = a->getWorldTransform().getOrigin() - b->getWorldTransform().getOrigin();
  const btVector3 v = velocityAt(a, a->getWorldTransform().getOrigin()) - velocityAt(b, b->getWorldTransform().getOrigin());
  const double vv = v.length2(), rv = r.dot(v), gap = r.length2() - reach * reach;
  const double discriminant = rv * rv - vv * gap;
  if (!(vv > 0) || rv >= 0 || discriminant < 0) return std::nullopt;
  if (gap <= 0) return 0.0;
  // The first root, in the form that does not cancel.
  return gap / (-rv + std::sqrt(discriminant));
}

// The fastest any point of `object` moves, m/s: its centre's speed and its
// spin times the farthest its shape reaches from the centre (a corner of
// the shape's own box, which need not be centred on it).
double fastestPoint(const btCollisionObject& object) {
  const btRigidBody* body = btRigidBody::upcast(&object);
  if (!body || body->isStaticOrKinematicObject()) return 0.0;
  btVector3 low, high;
  object.getCollisionShape()->getAabb(btTransform::getIdentity(), low, high);
  const btVector3 reach(std::max(-low.x(), high.x()), std::max(-low.y(), high.y()), std::max(-low.z(), high.z()));
  return body->getLinearVelocity().length() + body->getAngularVelocity().length() * reach.length();
}

}  // namespace

ImpactScan::ImpactScan(btDispatcher& dispatcher, Storage& storage) : dispatcher_(dispatcher), storage_(storage) {
  storage_.held.clear();
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold.getContactPoint(p);
      if (point.getDistance() > kTouching || bounced(point)) continue;
      storage_.held.insert(manifold.getBody0());
      storage_.held.insert(manifold.getBody1());
    }
  }
}

bool ImpactScan::held(const btCollisionObject* object) const {
  return storage_.held.contains(object);
}

double ImpactScan::accelerationTowards(const btCollisionObject& a, const btCollisionObject& b,
                                       const btVector3& normalOnB) const {
  return -(accelerationOf(a) - accelerationOf(b)).dot(normalOnB);
}

btVector3 ImpactScan::accelerationOf(const btCollisionObject& object) const {
  const btRigidBody* body = btRigidBody::upcast(&object);
  if (!body || body->getInvMass() == 0 || held(&object)) return btVector3(0, 0, 0);
  return body->getTotalForce() * body->getInvMass();
}

double ImpactScan::closingAcceleration(const btPersistentManifold& manifold, const btManifoldPoint& point) const {
  return accelerationTowards(*manifold.getBody0(), *manifold.getBody1(), point.m_normalWorldOnB);
}

double ImpactScan::earliestImpact(double horizon, double impactSpeed, BodySet* eventful) const {
  double earliest = horizon;
  for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
    const btPersistentManifold& manifold = *dispatcher_.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold.getContactPoint(p);
      if (point.getDistance() <= kTouching) continue;
      const double speed = closingSpeed(manifold, point), accel = closingAcceleration(manifold, point);
      const double t = accel == 0 ? ballsMeet(manifold).value_or(timeToClose(point.getDistance(), speed, accel))
                                  : timeToClose(point.getDistance(), speed, accel);
      if (!(t < horizon) || !(speed + accel * t > impactSpeed)) continue;
      earliest = std::min(earliest, t);
      if (eventful) eventful->insert(manifold.getBody0()), eventful->insert(manifold.getBody1());
    }
  }
  return earliest;
}

double ImpactScan::earliestSeparatedImpact(btOverlappingPairCache& pairs, double horizon, double impactSpeed,
                                           BodySet* eventful) const {
  double earliest = horizon;
  btManifoldArray& manifolds = storage_.manifolds;
  btBroadphasePairArray& array = pairs.getOverlappingPairArray();
  for (int i = 0; i < array.size(); ++i) {
    const btBroadphasePair& pair = array[i];
    const auto& a = *static_cast<const btCollisionObject*>(pair.m_pProxy0->m_clientObject);
    const auto& b = *static_cast<const btCollisionObject*>(pair.m_pProxy1->m_clientObject);
    if (storage_.setAside && (storage_.setAside->contains(&a) || storage_.setAside->contains(&b))) continue;
    const double fastest = fastestPoint(a) + fastestPoint(b);
    if (fastest <= impactSpeed) continue;
    manifolds.resize(0);
    if (pair.m_algorithm) pair.m_algorithm->getAllContactManifolds(manifolds);
    bool found = false;
    for (int m = 0; m < manifolds.size(); ++m) found |= manifolds[m]->getNumContacts() > 0;
    if (found) continue;  // earliestImpact has its points
    // The farthest the pair can close within the horizon: pieces whose
    // boxes are farther apart cannot meet in it, and GJK is spared.
    const double fastestAccel = accelerationOf(a).length() + accelerationOf(b).length();
    const double reach = (fastest + 0.5 * fastestAccel * horizon) * horizon + kTouching;
    for (const auto& [shapeA, placeA] : convexPieces(a)) {
      for (const auto& [shapeB, placeB] : convexPieces(b)) {
        if (shapeA != nullptr && shapeB != nullptr && boxGap(*shapeA, placeA, *shapeB, placeB) > reach) continue;
        if (shapeA == nullptr && shapeB == nullptr) continue;
        const btPointCollector closest = closestOf(shapeA, placeA, a, shapeB, placeB, b);
        if (!closest.m_hasResult || closest.m_distance <= kTouching) continue;
        // A point of manifold form: the normal on B, from B towards A.
        const btVector3 onB = closest.m_pointInWorld;
        const btVector3 onA = onB + closest.m_normalOnBInWorld * closest.m_distance;
        const btVector3& n = closest.m_normalOnBInWorld;
        const double speed = -(velocityAt(&a, onA) - velocityAt(&b, onB)).dot(n);
        const double accel = accelerationTowards(a, b, n);
        // To half the touching distance past touch: the separating-axis
        // test reports faces that only touch as apart.
        const double t = timeToClose(closest.m_distance + 0.5 * kTouching, speed, accel);
        if (!(t < horizon) || !(speed + accel * t > impactSpeed)) continue;
        earliest = std::min(earliest, t);
        if (eventful) eventful->insert(&a), eventful->insert(&b);
      }
    }
  }
  return earliest;
}

void ImpactScan::holdMeanVelocity(double length, const BodySet& stopping,
                                  std::vector<std::pair<btManifoldPoint*, btScalar>>& saved, BodySet& bodies) const {
  const auto free = [&](const btCollisionObject* o) {
    return !o->isStaticOrKinematicObject() && !held(o) && !stopping.contains(o);
  };
  for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
    btPersistentManifold& manifold = *dispatcher_.getManifoldByIndexInternal(m);
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      btManifoldPoint& point = manifold.getContactPoint(p);
      const double gap = point.getDistance();
      if (!bounced(point) && (gap <= kTouching || !(free(manifold.getBody0()) || free(manifold.getBody1())))) continue;
      const double mean = 2.0 * gap - closingSpeed(manifold, point) * length;
      if (!(mean > gap)) continue;
      saved.emplace_back(&point, point.getDistance());
      point.setDistance(mean);
      bodies.insert(manifold.getBody0());
      bodies.insert(manifold.getBody1());
    }
  }
}

}  // namespace tabletop
