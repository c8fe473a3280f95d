#include "physics/collision/Reach.h"

#include <BulletCollision/CollisionShapes/btCompoundShape.h>

#include <cmath>

namespace tabletop {
namespace {

// How far apart, m, a body and what it rests on may be at a point of
// theirs and still touch there (points are found to rounding, and a
// resting body bobs by micrometres).
constexpr double kOnSurface = 1e-4;

// Whether `body`'s box, grown by `reach`, stays within `support`'s box
// across `up`: the body cannot come to the support's edge in the step
// (a plane has none).
bool staysOver(const btCollisionObject& body, const btCollisionObject& support, const btVector3& up,
               double reach) {
  if (support.getCollisionShape()->getShapeType() == STATIC_PLANE_PROXYTYPE) return true;
  btVector3 low, high, under, over;
  body.getCollisionShape()->getAabb(body.getWorldTransform(), low, high);
  support.getCollisionShape()->getAabb(support.getWorldTransform(), under, over);
  for (int i = 0; i < 3; ++i) {
    if (std::fabs(up[i]) >= 0.5) continue;  // along up
    if (low[i] - reach < under[i] || high[i] + reach > over[i]) return false;
  }
  return true;
}

// Collects whether any object the broadphase finds overlapping a box, but
// the body itself and what it slides on, is near it (a plane only if the
// box reaches it, a compound only if a child's box overlaps it).
class Near : public btBroadphaseAabbCallback {
 public:
  Near(btCollisionWorld& world, const btRigidBody& self, double reach, double slideStep)
      : world_(&world), self_(&self), reach_(reach), slideStep_(slideStep) {
    self.getCollisionShape()->getAabb(self.getWorldTransform(), low_, high_);
    const btVector3 around(reach, reach, reach);
    low_ -= around;
    high_ += around;
  }
  const btVector3& low() const { return low_; }
  const btVector3& high() const { return high_; }
  bool process(const btBroadphaseProxy* proxy) override {
    const auto* other = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    if (other == self_ || found_) return true;
    if (slideStep_ > 0 && slidesOn(*world_->getPairCache(), *self_, *other, slideStep_, reach_)) return true;
    const btCollisionShape& shape = *other->getCollisionShape();
    if (shape.getShapeType() == STATIC_PLANE_PROXYTYPE) {
      found_ = reachesPlane(*other);
    } else if (shape.isCompound()) {
      found_ = reachesChild(*other);
    } else {
      found_ = true;
    }
    return true;
  }
  bool found() const { return found_; }

 private:
  // Whether the box's corner deepest below the plane comes within the
  // plane's margin of it.
  bool reachesPlane(const btCollisionObject& object) const {
    const auto& plane = static_cast<const btStaticPlaneShape&>(*object.getCollisionShape());
    const btTransform& place = object.getWorldTransform();
    const btVector3 normal = place.getBasis() * plane.getPlaneNormal();
    const btScalar level = plane.getPlaneConstant() + normal.dot(place.getOrigin());
    btVector3 deepest;
    for (int i = 0; i < 3; ++i) deepest[i] = normal[i] > 0 ? low_[i] : high_[i];
    return normal.dot(deepest) <= level + plane.getMargin();
  }

  // Whether the box overlaps a child's own box: a compound's box holds all
  // of them, and the table's legs' spans the whole space under its top.
  bool reachesChild(const btCollisionObject& object) const {
    const auto& compound = static_cast<const btCompoundShape&>(*object.getCollisionShape());
    for (int c = 0; c < compound.getNumChildShapes(); ++c) {
      btVector3 low, high;
      compound.getChildShape(c)->getAabb(object.getWorldTransform() * compound.getChildTransform(c), low, high);
      if (TestAabbAgainstAabb2(low, high, low_, high_)) return true;
    }
    return false;
  }

  btCollisionWorld* world_;
  const btRigidBody* self_;
  double reach_;
  btVector3 low_, high_;
  double slideStep_;
  bool found_ = false;
};

}  // namespace

bool nearAnything(btCollisionWorld& world, const btRigidBody& body, double reach, double slideStep) {
  Near near(world, body, reach, slideStep);
  world.getBroadphase()->aabbTest(near.low(), near.high(), near);
  return near.found();
}

bool slidesOn(btOverlappingPairCache& pairs, const btRigidBody& body, const btCollisionObject& support,
              double timestep, double reach) {
  const btVector3 gravity = body.getGravity();
  if (!(gravity.length2() > 0)) return false;
  const btVector3 up = -gravity.normalized();
  if (!staysOver(body, support, up, reach)) return false;
  // findPair only reads the proxies, though Bullet declares them mutable.
  btBroadphasePair* pair = pairs.findPair(const_cast<btBroadphaseProxy*>(body.getBroadphaseHandle()),
                                          const_cast<btBroadphaseProxy*>(support.getBroadphaseHandle()));
  if (pair == nullptr || pair->m_algorithm == nullptr) return false;
  btManifoldArray manifolds;
  pair->m_algorithm->getAllContactManifolds(manifolds);
  const btRigidBody* under = btRigidBody::upcast(&support);
  for (int m = 0; m < manifolds.size(); ++m) {
    const btPersistentManifold& manifold = *manifolds[m];
    const bool isA = manifold.getBody0() == &body;
    for (int p = 0; p < manifold.getNumContacts(); ++p) {
      const btManifoldPoint& point = manifold.getContactPoint(p);
      if (point.getDistance() > kOnSurface) continue;
      // The normal points from B to A: from the support to the body.
      const btVector3 normal = isA ? point.m_normalWorldOnB : -point.m_normalWorldOnB;
      if (normal.dot(up) < 0.7) continue;
      const btVector3& at = isA ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
      btVector3 v = body.getVelocityInLocalPoint(at - body.getCenterOfMassPosition());
      if (under != nullptr) v -= under->getVelocityInLocalPoint(at - under->getCenterOfMassPosition());
      if (v.dot(normal) >= -gravity.length() * timestep) return true;
    }
  }
  return false;
}

}  // namespace tabletop
