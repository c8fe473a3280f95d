#pragma once

#include <memory>
#include <string>

#include <btBulletDynamicsCommon.h>

#include "core/Colour.h"
#include "core/EntityPositionStatus.h"
#include "core/Material.h"
#include "core/ShapeKind.h"
#include "core/Support.h"

namespace tabletop {

class Table;

/// The report's Shapes base class (report 3) on Bullet: a named, coloured
/// solid that owns its btCollisionShape and, once it is an entity, its
/// btRigidBody. Geometry only: drawing lives elsewhere.
///
/// The local frame's origin is the centre of mass and its axes are the
/// principal axes of inertia, so the body's transform is the shape's pose.
class Shape {
 public:
  virtual ~Shape();
  Shape(const Shape&) = delete;
  Shape& operator=(const Shape&) = delete;

  const std::string& name() const { return name_; }
  virtual ShapeKind kind() const = 0;
  /// Volume, m^3.
  virtual double volume() const = 0;
  /// Principal moments of inertia about the centre of mass, kg*m^2, in
  /// closed form for `mass` spread uniformly.
  virtual btVector3 localInertia(double mass) const = 0;
  /// Half extents of the local bounding box, metres.
  virtual btVector3 halfExtents() const = 0;
  /// Distance from the centre of mass to the farthest point, metres, or a
  /// bound on it (the bounding box's half diagonal unless a shape knows
  /// better).
  virtual double boundingRadius() const { return halfExtents().length(); }
  /// How far a point of the surface can move per radian the body turns,
  /// metres: at most the farthest point's distance from the centre of mass.
  virtual double turningReach() const { return boundingRadius(); }
  /// Distance from the centre of mass down to the lowest point, metres.
  virtual double below() const { return halfExtents().y(); }
  /// Distance from the centre of mass up to the highest point, metres.
  virtual double above() const { return halfExtents().y(); }
  /// Distance from the centre to the surface along a horizontal local unit
  /// direction: where a push along -`direction` meets the body (report 3.5).
  virtual double surfaceDistance(const btVector3& direction) const = 0;
  /// How far the entity's collision surface reaches along the world unit
  /// `direction` in its current pose: the largest x.direction over its
  /// points, metres (Bullet's support point; every entity shape is convex).
  /// Needs the body.
  double reach(const btVector3& direction) const;
  /// True when the shape has faces a push arrow follows (cube, box).
  virtual bool hasFaces() const { return false; }

  const btCollisionShape& collisionShape() const { return *collisionShape_; }
  btCollisionShape& collisionShape() { return *collisionShape_; }

  /// Makes this shape a dynamic entity: a rigid body of `mass` kg at `pose`.
  void createBody(double mass, const Material& material, const btTransform& pose);
  /// The entity's body; null until createBody().
  btRigidBody* body() { return body_.get(); }
  const btRigidBody* body() const { return body_.get(); }
  double mass() const { return mass_; }
  const Material& material() const { return material_; }

  const Colour& colour() const { return colour_; }
  void setColour(const Colour& c) { colour_ = c; }

  /// Centre of mass in world space.
  btVector3 position() const;
  /// Heading of the local +X axis about world +Y, degrees (report 3.8 sense).
  double yawDegrees() const;

  /// The report's PositionStatus of this entity.
  EntityPositionStatus status() const { return status_; }
  /// The report's CheckBoundary (3.4): OnTable becomes DropFrom...Edge once
  /// the centre passes an edge. Returns true when the status changed.
  bool checkBoundary(const Table& table);
  /// Sets the status as the status rule gives it (EntityPositionStatus.h).
  void setStatus(EntityPositionStatus s) { status_ = s; }

  /// What this entity rests on; none while nothing holds it up.
  const Support& support() const { return support_; }
  void setSupport(Support support) { support_ = std::move(support); }

 protected:
  Shape(std::string name, std::unique_ptr<btCollisionShape> shape);

 private:
  std::string name_;
  Colour colour_;
  Material material_;
  double mass_ = 0.0;
  std::unique_ptr<btCollisionShape> collisionShape_;
  std::unique_ptr<btRigidBody> body_;
  EntityPositionStatus status_ = EntityPositionStatus::OnTable;
  Support support_;
};

}  // namespace tabletop
