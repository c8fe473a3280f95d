#pragma once

#include "physics/Shape.h"

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

}  // namespace tabletop
