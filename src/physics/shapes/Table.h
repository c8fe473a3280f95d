#pragma once

#include <array>
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "core/EntityPositionStatus.h"
#include "core/TableSpec.h"
#include "physics/shapes/Cylinder.h"
#include "physics/shapes/SolidBox.h"
#include "core/TableEdges.h"

namespace tabletop {

/// The report's Table: a static entity made of a SolidBox top on four
/// Cylinder legs, as one static btRigidBody with a btCompoundShape. Its top
/// edges are the report's critical boundary (report 3.4).
///
/// With `separateLegs`, the compound holds the top alone and the legs are
/// a second static compound, legsBody(), which the World adds only once a
/// body can reach them (Settings::legsWhenReachable).
class Table {
 public:
  explicit Table(const TableSpec& spec, bool separateLegs = false);
  ~Table();
  Table(const Table&) = delete;
  Table& operator=(const Table&) = delete;

  const TableSpec& spec() const { return spec_; }
  /// X_L, the left edge (smallest X), metres.
  double xLeft() const { return spec_.centreX - 0.5 * spec_.width; }
  /// X_R, the right edge.
  double xRight() const { return spec_.centreX + 0.5 * spec_.width; }
  /// Z_B, the back edge (smallest Z).
  double zBack() const { return spec_.centreZ - 0.5 * spec_.depth; }
  /// Z_F, the front edge (largest Z; the report's Z_T).
  double zFront() const { return spec_.centreZ + 0.5 * spec_.depth; }
  /// Height of the top surface above the ground.
  double topHeight() const { return spec_.height; }
  /// The four edges, as the report's rules take them.
  TableEdges edges() const;

  /// The report's drop test (3.4, dropStatus) for a centre at (x, z).
  EntityPositionStatus statusAt(double x, double z) const;

  const SolidBox& top() const { return *top_; }
  const std::array<std::unique_ptr<Cylinder>, 4>& legs() const { return legs_; }
  /// Centre of each leg in world space (same order as legs()).
  btVector3 legCentre(int i) const;

  btRigidBody& body() { return *body_; }
  const btRigidBody& body() const { return *body_; }
  /// The legs' own static body, when they are separate; null otherwise.
  btRigidBody* legsBody() { return legsBody_.get(); }
  /// Height of the top's underside, the highest point of the legs.
  double undersideHeight() const { return spec_.height - spec_.thickness; }

 private:
  std::unique_ptr<btRigidBody> makeStaticBody(btCompoundShape& shape) const;

  TableSpec spec_;
  std::unique_ptr<SolidBox> top_;
  std::array<std::unique_ptr<Cylinder>, 4> legs_;
  std::vector<std::unique_ptr<btCollisionShape>> children_;  // the compounds' shapes: top, then legs
  std::unique_ptr<btCompoundShape> compound_;
  std::unique_ptr<btRigidBody> body_;
  std::unique_ptr<btCompoundShape> legsCompound_;
  std::unique_ptr<btRigidBody> legsBody_;
};

}  // namespace tabletop
