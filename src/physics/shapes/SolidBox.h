#pragma once

#include "physics/shapes/Shape.h"

namespace tabletop {

/// The report's SolidBox: width (X) by height (Y) by depth (Z), metres. Used
/// for the table top, and as an entity.
class SolidBox : public Shape {
 public:
  SolidBox(std::string name, double width, double height, double depth);

  double width() const { return 2.0 * half_.x(); }
  double height() const { return 2.0 * half_.y(); }
  double depth() const { return 2.0 * half_.z(); }

  ShapeKind kind() const override { return ShapeKind::SolidBox; }
  double volume() const override;
  btVector3 localInertia(double mass) const override;  // m (b^2 + c^2) / 12
  btVector3 halfExtents() const override { return half_; }
  double surfaceDistance(const btVector3& direction) const override;
  bool hasFaces() const override { return true; }

 private:
  btVector3 half_;
};

/// Builds `box`'s faces and edges for polyhedral clipping (Bullet's
/// separating-axis test) with its corners exactly at its half extents.
/// Bullet's hull step (initializePolyhedralFeatures) rounds them through
/// integers, so many box sizes came out a few micrometres small; a cube
/// seated on such a cube then read as above it, not touching, and fell
/// freely for a step into it (docs/bullet-corrections.md).
/// `box` must have no polyhedron yet.
void initializeExactBoxFeatures(btBoxShape& box);

}  // namespace tabletop
