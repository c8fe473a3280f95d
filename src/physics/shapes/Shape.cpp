#include "physics/shapes/Shape.h"

#include <cmath>

#include "core/Angle.h"
#include "physics/shapes/Table.h"

namespace tabletop {

Shape::Shape(std::string name, std::unique_ptr<btCollisionShape> shape)
    : name_(std::move(name)), collisionShape_(std::move(shape)) {}

Shape::~Shape() = default;

void Shape::createBody(double mass, const Material& material, const btTransform& pose) {
  mass_ = mass;
  material_ = material;
  // No motion state: the world steps at a fixed rate and nothing is
  // interpolated, so the body's own transform is the state.
  btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, collisionShape_.get(),
                                                localInertia(mass));
  info.m_startWorldTransform = pose;
  info.m_friction = material.friction;
  info.m_rollingFriction = 0;  // rolling and spinning friction:
  info.m_spinningFriction = 0;  // applied by DynamicsWorld
  info.m_restitution = material.restitution;
  body_ = std::make_unique<btRigidBody>(info);
}

btVector3 Shape::position() const {
  return body_ ? body_->getWorldTransform().getOrigin() : btVector3(0, 0, 0);
}

double Shape::yawDegrees() const {
  if (!body_) return 0.0;
  // Local +X in world space; a turn by yaw about +Y maps it to
  // (cos yaw, 0, -sin yaw).
  const btMatrix3x3& r = body_->getWorldTransform().getBasis();
  return toDegrees(std::atan2(-double(r[2][0]), double(r[0][0])));
}

bool Shape::checkBoundary(const Table& table) {
  if (status_ != EntityPositionStatus::OnTable) return false;
  const btVector3 c = position();
  status_ = table.statusAt(c.x(), c.z());
  return status_ != EntityPositionStatus::OnTable;
}

double Shape::reach(const btVector3& direction) const {
  const auto& convex = static_cast<const btConvexShape&>(*collisionShape_);
  const btTransform& pose = body_->getWorldTransform();
  return (pose * convex.localGetSupportingVertex(pose.getBasis().transpose() * direction)).dot(direction);
}

}  // namespace tabletop
