#include "physics/Reach.h"

namespace tabletop {
namespace {

// Collects whether any object the broadphase finds overlapping a box, but
// the body itself, is near it (a plane only if the box reaches it).
class Near : public btBroadphaseAabbCallback {
 public:
  Near(const btCollisionObject& self, const btVector3& low, const btVector3& high)
      : self_(&self), low_(low), high_(high) {}
  bool process(const btBroadphaseProxy* proxy) override {
    const auto* other = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    if (other == self_ || found_) return true;
    found_ = other->getCollisionShape()->getShapeType() != STATIC_PLANE_PROXYTYPE || reachesPlane(*other);
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

  const btCollisionObject* self_;
  btVector3 low_, high_;
  bool found_ = false;
};

}  // namespace

bool nearAnything(btCollisionWorld& world, const btCollisionObject& body, double reach) {
  btVector3 low, high;
  body.getCollisionShape()->getAabb(body.getWorldTransform(), low, high);
  const btVector3 around(reach, reach, reach);
  Near near(body, low - around, high + around);
  world.getBroadphase()->aabbTest(low - around, high + around, near);
  return near.found();
}

}  // namespace tabletop
