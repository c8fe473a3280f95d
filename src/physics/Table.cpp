#include "physics/Table.h"

namespace tabletop {

Table::Table(const TableSpec& spec, bool separateLegs) : spec_(spec) {
  const double legHeight = spec.height - spec.thickness;
  top_ = std::make_unique<SolidBox>("table top", spec.width, spec.thickness, spec.depth);
  for (auto& leg : legs_) {
    leg = std::make_unique<Cylinder>("table leg", spec.legRadius, spec.legRadius, legHeight);
  }

  // The compounds' frame sits on the ground under the table's centre; the
  // children do not own their shapes (the SolidBox and Cylinders do).
  compound_ = std::make_unique<btCompoundShape>(false, separateLegs ? 1 : 5);
  btTransform local;
  local.setIdentity();
  local.setOrigin(btVector3(0, spec.height - 0.5 * spec.thickness, 0));
  compound_->addChildShape(local, &top_->collisionShape());
  btCompoundShape* legsHolder = compound_.get();
  if (separateLegs) {
    legsCompound_ = std::make_unique<btCompoundShape>(false, 4);
    legsHolder = legsCompound_.get();
  }
  for (int i = 0; i < 4; ++i) {
    local.setOrigin(legCentre(i) - btVector3(spec.centreX, 0, spec.centreZ));
    legsHolder->addChildShape(local, &legs_[i]->collisionShape());
  }

  body_ = makeStaticBody(*compound_);
  if (legsCompound_) legsBody_ = makeStaticBody(*legsCompound_);
}

std::unique_ptr<btRigidBody> Table::makeStaticBody(btCompoundShape& shape) const {
  btTransform pose;
  pose.setIdentity();
  pose.setOrigin(btVector3(spec_.centreX, 0, spec_.centreZ));
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, &shape);
  info.m_startWorldTransform = pose;
  info.m_friction = spec_.material.friction;
  info.m_rollingFriction = 0;  // rolling and spinning friction:
  info.m_spinningFriction = 0;  // applied by DynamicsWorld
  info.m_restitution = spec_.material.restitution;
  return std::make_unique<btRigidBody>(info);
}

Table::~Table() = default;

btVector3 Table::legCentre(int i) const {
  const Vec3 c = spec_.legCentre(i);
  return btVector3(c.x, c.y, c.z);
}

rules::TableEdges Table::edges() const { return {xLeft(), xRight(), zBack(), zFront()}; }

EntityPositionStatus Table::statusAt(double x, double z) const {
  return rules::dropStatus({x, 0.0, z}, edges());
}

}  // namespace tabletop
