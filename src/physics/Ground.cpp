#include "physics/Ground.h"

namespace tabletop {

Ground::Ground(const Material& material)
    : material_(material), plane_(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0.0)) {
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, plane_.get());
  info.m_friction = material.friction;
  info.m_rollingFriction = 0;  // rolling and spinning friction:
  info.m_spinningFriction = 0;  // applied by DynamicsWorld
  info.m_restitution = material.restitution;
  body_ = std::make_unique<btRigidBody>(info);
}

Ground::~Ground() = default;

}  // namespace tabletop
