#include "physics/shapes/Table.h"

#include "physics/shapes/PaddedShape.h"

namespace tabletop {

Table::Table(const TableSpec& spec, bool separateLegs) : spec_(spec) {
  const double legHeight = spec.height - spec.thickness;
  top_ = std::make_unique<SolidBox>("table top", spec.width, spec.thickness, spec.depth);
  for (auto& leg : legs_) {
    leg = std::make_unique<Cylinder>("table leg", spec.legRadius, spec.legRadius, legHeight);
  }

  // The compounds' children are the top's and legs' shapes with their
  // bounding boxes padded by Bullet's contact breaking threshold
  // (PaddedShape); the compounds do not own them.
  const auto& topBox = static_cast<const btBoxShape&>(top_->collisionShape());
  auto top = std::make_unique<PaddedShape<btBoxShape>>(gContactBreakingThreshold, topBox.getHalfExtentsWithMargin());
  top->setMargin(topBox.getMargin());
  initializeExactBoxFeatures(*top);
  children_.push_back(std::move(top));
  for (const auto& leg : legs_) {
    const auto& cylinder = static_cast<const btCylinderShape&>(leg->collisionShape());
    auto padded =
        std::make_unique<PaddedShape<btCylinderShape>>(gContactBreakingThreshold, cylinder.getHalfExtentsWithMargin());
    padded->setMargin(cylinder.getMargin());
    children_.push_back(std::move(padded));
  }

  // The compounds' frame sits on the ground under the table's centre.
  compound_ = std::make_unique<btCompoundShape>(false, separateLegs ? 1 : 5);
  btTransform local;
  local.setIdentity();
  local.setOrigin(btVector3(0, spec.height - 0.5 * spec.thickness, 0));
  compound_->addChildShape(local, children_[0].get());
  btCompoundShape* legsHolder = compound_.get();
  if (separateLegs) {
    legsCompound_ = std::make_unique<btCompoundShape>(false, 4);
    legsHolder = legsCompound_.get();
  }
  for (int i = 0; i < 4; ++i) {
    local.setOrigin(legCentre(i) - btVector3(spec.centreX, 0, spec.centreZ));
    legsHolder->addChildShape(local, children_[static_cast<std::size_t>(i) + 1].get());
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

TableEdges Table::edges() const { return {xLeft(), xRight(), zBack(), zFront()}; }

EntityPositionStatus Table::statusAt(double x, double z) const {
  return dropStatus({x, 0.0, z}, edges());
}

}  // namespace tabletop
