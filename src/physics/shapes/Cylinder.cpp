#include "physics/shapes/Cylinder.h"

#include <algorithm>

#include "core/Angle.h"
#include "core/ShapeGeometry.h"
#include "physics/shapes/CollisionMargin.h"

namespace tabletop {
namespace {

constexpr int kHullSegments = 32;

std::unique_ptr<btCollisionShape> makeCylinder(double R, double r, double h) {
  const double margin = collisionMargin(std::min(std::max(R, r), 0.5 * h));
  if (R == r) {
    // btCylinderShape keeps its outer size and takes the margin from inside.
    auto c = std::make_unique<btCylinderShape>(btVector3(R, 0.5 * h, R));
    c->setMargin(margin);
    return c;
  }
  // A truncated cone as a convex hull of two rings around the centroid, a
  // cone as one ring and its point. A hull grows outwards by its margin, so
  // the rings and the point are drawn in by it.
  auto hull = std::make_unique<btConvexHullShape>();
  const double yc = ShapeGeometry::cylinder(R, r, h).centroidHeight();
  const double smaller = std::min(R, r) > 0 ? std::min(R, r) : std::max(R, r);
  const double m = std::min(margin, 0.5 * smaller);
  for (int i = 0; i < kHullSegments; ++i) {
    const double a = 2.0 * kPi * i / kHullSegments;
    const double c = std::cos(a), s = std::sin(a);
    if (R > 0) hull->addPoint(btVector3((R - m) * c, -yc + m, (R - m) * s), false);
    if (r > 0) hull->addPoint(btVector3((r - m) * c, h - yc - m, (r - m) * s), false);
  }
  if (R == 0) hull->addPoint(btVector3(0, -yc + m, 0), false);
  if (r == 0) hull->addPoint(btVector3(0, h - yc - m, 0), false);
  hull->setMargin(m);
  hull->recalcLocalAabb();
  return hull;
}

}  // namespace

Cylinder::Cylinder(std::string name, double baseRadius, double topRadius, double height)
    : Shape(std::move(name), makeCylinder(baseRadius, topRadius, height)),
      baseRadius_(baseRadius),
      topRadius_(topRadius),
      height_(height) {}

ShapeGeometry Cylinder::geometry() const { return ShapeGeometry::cylinder(baseRadius_, topRadius_, height_); }

double Cylinder::centroidHeight() const { return geometry().centroidHeight(); }

double Cylinder::volume() const { return geometry().volume(); }

btVector3 Cylinder::localInertia(double mass) const {
  const Vec3 i = geometry().inertia(mass);
  return btVector3(i.x, i.y, i.z);
}

btVector3 Cylinder::halfExtents() const {
  const double rmax = std::max(baseRadius_, topRadius_);
  return btVector3(rmax, std::max(below(), above()), rmax);
}

// At the centroid's height the radius is interpolated between base and top.
double Cylinder::surfaceDistance(const btVector3&) const {
  const double f = centroidHeight() / height_;
  return baseRadius_ + (topRadius_ - baseRadius_) * f;
}

}  // namespace tabletop
