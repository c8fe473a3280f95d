#pragma once

#include "core/ShapeGeometry.h"
#include "physics/shapes/Shape.h"

namespace tabletop {

/// The report's Cylinder (report 3): base radius, top radius and height,
/// metres, axis along Y, as gluCylinder draws it. Equal radii make a true
/// cylinder (the table legs); different radii a truncated cone. The local
/// origin is the centre of mass, `centroidHeight()` above the base.
class Cylinder : public Shape {
 public:
  Cylinder(std::string name, double baseRadius, double topRadius, double height);

  double baseRadius() const { return baseRadius_; }
  double topRadius() const { return topRadius_; }
  double height() const { return height_; }
  /// Height of the centre of mass above the base, metres.
  double centroidHeight() const;
  /// Its size and mass properties, Bullet-free.
  ShapeGeometry geometry() const;

  ShapeKind kind() const override { return ShapeKind::Cylinder; }
  double volume() const override;
  btVector3 localInertia(double mass) const override;
  btVector3 halfExtents() const override;
  double below() const override { return centroidHeight(); }
  double above() const override { return height_ - centroidHeight(); }
  double surfaceDistance(const btVector3& direction) const override;

 private:
  double baseRadius_;
  double topRadius_;
  double height_;
};

}  // namespace tabletop
