#include "physics/shapes/Ground.h"

namespace tabletop {
namespace {

// The plane y = 0 bounded as the half-space it is: below it, unbounded;
// above it, nothing. Bullet gives every plane an infinite bounding box, so
// the broadphase pairs it with every body, and each pair runs the
// plane-convex test every step; with this box only bodies whose own box
// (grown by the contact breaking threshold) comes down to the floor pair.
class FloorPlane : public btStaticPlaneShape {
 public:
  FloorPlane() : btStaticPlaneShape(btVector3(0, 1, 0), 0.0) {}
  void getAabb(const btTransform& t, btVector3& aabbMin, btVector3& aabbMax) const override {
    btStaticPlaneShape::getAabb(t, aabbMin, aabbMax);
    aabbMax.setY(t.getOrigin().y() + getMargin());
  }
};

}  // namespace

Ground::Ground(const Material& material, bool bounded)
    : material_(material),
      plane_(bounded ? std::make_unique<FloorPlane>()
                     : std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0.0)) {
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, plane_.get());
  info.m_friction = material.friction;
  info.m_rollingFriction = 0;  // rolling and spinning friction:
  info.m_spinningFriction = 0;  // applied by DynamicsWorld
  info.m_restitution = material.restitution;
  body_ = std::make_unique<btRigidBody>(info);
}

Ground::~Ground() = default;

}  // namespace tabletop
