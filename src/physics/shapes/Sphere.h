#pragma once

#include "physics/shapes/Shape.h"

namespace tabletop {

/// The report's Sphere (report 3): a ball of `radius` metres.
class Sphere : public Shape {
 public:
  Sphere(std::string name, double radius);

  double radius() const { return radius_; }

  ShapeKind kind() const override { return ShapeKind::Sphere; }
  double volume() const override;
  btVector3 localInertia(double mass) const override;  // 2/5 m r^2
  btVector3 halfExtents() const override { return btVector3(radius_, radius_, radius_); }
  double surfaceDistance(const btVector3&) const override { return radius_; }
  double boundingRadius() const override { return radius_; }
  // Turning about its centre, a sphere's surface stays where it was.
  double turningReach() const override { return 0.0; }

 private:
  double radius_;
};

}  // namespace tabletop
